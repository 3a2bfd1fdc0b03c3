"""docs/contours.md's tables: full circles of several radii, each at the C_R alp85 gcode chooses
and at one coarser and one finer, run on the emulated board; the measured toolpath error beside
the paper's bound, and the T-states of one segment's arithmetic (ALOOP to AHAND). Beside them, on
the host: the same circle with X* rounded to the nearest step (the master before), and the least
error any choice of end points could give (best_rounding.py).

  python3 sweep.py ALP85 WORKDIR
"""
import math
import os
import re
import subprocess
import sys

import best_rounding
import check_path
import contour_ref as ref
import mkscripts
from best_rounding import rule

TIMING = """motor ideal
monitor
firmware thesis-fixed
firmware master
load {hex}
reset
wait display "-ALP 85-" timeout 1s
type R 7 3 0 0 0 EXEC
wait display "P=-     " timeout 100ms
type 1 EXEC
run until ALOOP timeout 200s
run until ALOOP timeout 200s
mark
run until AHAND timeout 1s
print time
"""


def patch(hexfile, cr):
    """The circle's entry (the second) with C_R forced and N recomputed as alp85 gcode does."""
    mem = ref.read_hex(hexfile)
    a = ref.TABLE + ref.ENTRY
    n = math.ceil(2 * math.pi * 2 ** cr - 1e-9) - 1
    mem[a + 1] = cr
    mem[a + 14], mem[a + 15] = n & 0xFF, n >> 8
    data = [mem[k] for k in range(ref.TABLE, ref.TABLE + 3 * ref.ENTRY)]
    lines = []
    for i in range(0, len(data), 16):
        rec = [16, (ref.TABLE + i) >> 8, (ref.TABLE + i) & 0xFF, 0] + data[i:i + 16]
        lines.append(":" + "".join(f"{b:02X}" for b in rec) + f"{(-sum(rec)) & 0xFF:02X}")
    open(hexfile, "w").write("\n".join(lines) + "\n:00000001FF\n")


def host_worst(path, nearest):
    """The largest distance of the tool from the circle on the host (contour_ref + the thesis rule)."""
    m = check_path.moves(path)[1]
    x, y, worst = path[0]["x"], path[0]["y"], 0.0
    for h in ref.handoffs(path, nearest):
        if h[3] == 1:
            for _, px, py in rule(x, y, h[1], h[2]):
                worst = max(worst, check_path.dist((px, py), m))
            x, y = h[1], h[2]
    return worst


def main():
    alp85, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    print("| R (mm) | R (steps) | C_R | segments | eps_A (eq. 9, steps) | polygon, inner chords | toolpath, largest | "
          "bound 1.5 eps_A + 1.80 | eps_A + 1 | nearest rounding (before) | best any end points | "
          "T-states per segment (ms) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r_mm in (2, 5, 10, 20, 50, 90):
        nc = os.path.join(work, f"r{r_mm}.nc")
        open(nc, "w").write(f"G21 G90\nG00 X{100 + r_mm} Y100\nG03 X{100 + r_mm} Y100 I-{r_mm} J0 F1500\n")
        base = os.path.join(work, f"r{r_mm}.hex")
        subprocess.run([alp85, "gcode", nc, "-o", base], check=True)
        chosen = ref.paths(ref.read_hex(base))[0][1]["cr"]
        for cr in sorted({max(1, chosen - 1), chosen, chosen + 1}):
            name = f"r{r_mm}_c{cr}"
            hexfile = os.path.join(work, name + ".hex")
            open(hexfile, "w").write(open(base).read())
            patch(hexfile, cr)
            text = mkscripts.script(name, hexfile)
            alp = os.path.join(work, name + ".alp")
            open(alp, "w").write(text)
            run = subprocess.run([alp85, "script", alp], capture_output=True, text=True)
            status = "" if run.returncode == 0 else " (run FAILED)"
            path = ref.paths(ref.read_hex(hexfile))[0]
            m = check_path.moves(path)[1]
            worst = check_path.worst_per_move(path, os.path.join(work, name + ".csv"))[0][1]
            tim = os.path.join(work, name + "_t.alp")
            open(tim, "w").write(TIMING.format(hex=hexfile))
            out = subprocess.run([alp85, "script", tim], capture_output=True, text=True).stdout
            t = re.search(r"time: ([0-9.]+) ms \((\d+) T-states\) since the mark", out)
            ea = ref.eps_a(cr, m["r"])
            mark = " *" if cr == chosen else ""
            print(f"| {r_mm} | {m['r']:.0f} | {cr}{mark} | {path[1]['n'] + 1} | {ea:.3f} | {m['poly'][0]:.3f} | "
                  f"{worst:.3f}{status} | {m['bound']:.3f} | {ea + 1:.3f} | {host_worst(path, True):.3f} | "
                  f"{best_rounding.best(round(m['r']), cr):.3f} | "
                  f"{t.group(2) + ' (' + t.group(1) + ')' if t else '?'} |")


if __name__ == "__main__":
    main()
