"""The arc bound of check_path (1.5 eps_A + 1.5 cos a + sin a <= 1.5 eps_A + sqrt(13)/2) on many
arcs at once, on the host: random centres, radii 2-100 mm, start angles, sweeps and directions, each
at the C_R alp85 gcode chooses and one either side; the master's end points from contour_ref.py (the
emulator hands over exactly these: CTest script:scripts/master/*), the tool positions between them
from the thesis line rule (firmware/thesis/check/pathrule.py, checked step by step against
thesis-fixed by CTest thesis-path:*). Exit 1 if any arc exceeds the bound.

  python3 bound_random.py [SEED] [COUNT]
"""
import math
import os
import random
import sys

import check_path
import contour_ref as ref

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../firmware/thesis/check"))
from pathrule import rule  # noqa: E402


def arc(rng):
    r = rng.uniform(40, 2000)
    c = (2100 + rng.randint(0, 40), 2100 + rng.randint(0, 40))
    a0 = rng.uniform(0, 2 * math.pi)
    start = (c[0] + round(r * math.cos(a0)), c[1] + round(r * math.sin(a0)))
    r = math.hypot(start[0] - c[0], start[1] - c[1])
    a0 = math.atan2(start[1] - c[1], start[0] - c[0])
    full = rng.random() < 0.3
    theta = 2 * math.pi if full else rng.uniform(0.2, 2 * math.pi - 0.2)
    s = rng.choice((1, -1))
    end = start if full else (c[0] + round(r * math.cos(a0 + s * theta)), c[1] + round(r * math.sin(a0 + s * theta)))
    k0 = max(1, math.ceil((math.log2(r) - 4) / 2))
    return start, c, r, theta, s, end, k0


def main():
    rng = random.Random(int(sys.argv[1]) if len(sys.argv) > 1 else 17)
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 60
    worst_margin, bad = -9.0, 0
    for _ in range(count):
        start, c, r, theta, s, end, k0 = arc(rng)
        for k in range(max(1, k0 - 1), k0 + 2):
            n = math.ceil(theta * 2 ** k - 1e-9) - 1
            e = dict(kind=4 if s == 1 else 3, cr=k, feed=750, x=end[0], y=end[1], z=0, cx=c[0], cy=c[1], n=n)
            rapid = dict(kind=1, cr=0, feed=1500, x=start[0], y=start[1], z=0, cx=0, cy=0, n=0)
            m = check_path.moves([rapid, e])[1]
            x, y, worst = start[0], start[1], 0.0
            for h in ref.handoffs([rapid, e]):
                if h[3] != 1:
                    continue
                for _, px, py in rule(x, y, h[1], h[2]):
                    worst = max(worst, check_path.dist((px, py), m))
                x, y = h[1], h[2]
            margin = worst - m["bound"]
            worst_margin = max(worst_margin, margin)
            if margin > 1e-9:
                bad += 1
                print(f"BAD R {r:.1f} C_R {k} centre {c} start {start} sweep {theta:.3f} s {s}: {worst:.3f} > {m['bound']:.3f}")
    print(f"{count} arcs at three C_R each: the largest error stands {-worst_margin:.3f} steps inside its bound")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
