"""check_path.py can fail: a recording of the circle example made on the host (contour_ref's
hand-overs, the thesis rule's steps between them), once as drawn - check_path must pass it - and
once with one position of the arc pushed 4 steps out - check_path must refuse it (exit 1).

  python3 check_path_fails.py CIRCLE.hex WORKDIR
"""
import os
import subprocess
import sys

import contour_ref as ref

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../firmware/thesis/check"))
from pathrule import rule  # noqa: E402

HEAD = "t_ms,x_count,y_count\n"


def recording(path):
    pts, x, y = [(0, 0)], 0, 0
    for h in ref.handoffs(path):
        if h[0] == "XY":
            pts += [(px, py) for _, px, py in rule(x, y, h[1], h[2])]
            x, y = h[1], h[2]
    return pts


def check(hexfile, pts, csv_path):
    with open(csv_path, "w") as f:
        f.write(HEAD + "".join(f"{i},{x},{y}\n" for i, (x, y) in enumerate(pts)))
    here = os.path.dirname(os.path.abspath(__file__))
    return subprocess.run([sys.executable, os.path.join(here, "check_path.py"), hexfile, csv_path],
                          capture_output=True, text=True).returncode


def main():
    hexfile, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    pts = recording(ref.paths(ref.read_hex(hexfile))[0])
    good = check(hexfile, pts, os.path.join(work, "drawn.csv"))
    i = len(pts) * 3 // 4  # a position on the arc; its centre from the table
    e = ref.paths(ref.read_hex(hexfile))[0][1]
    x, y = pts[i]
    dx, dy = x - e["cx"], y - e["cy"]
    r = (dx * dx + dy * dy) ** 0.5
    pts[i] = (x + round(4 * dx / r), y + round(4 * dy / r))  # 4 steps out: beyond 1.5 eps_A + 1.80 + 1
    bad = check(hexfile, pts, os.path.join(work, "pushed.csv"))
    print(f"check_path: as drawn exit {good} (0 expected), one position 4 steps out exit {bad} (1 expected)")
    sys.exit(0 if (good, bad) == (0, 1) else 1)


if __name__ == "__main__":
    main()
