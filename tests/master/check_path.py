"""The recorded toolpath of a master run against the true path and the paper's bounds.

  python3 check_path.py TABLE.hex RECORD.csv [--report]

The recorded X-Y positions (transducer counts, steps) are taken in time order, move by move of
path 1 (a move ends when the tool stands on its end point, having left it). Per move, the largest
distance from the true line or arc is compared with:
  line: the thesis rule's staircase bound cos a + sin a (contour_ref.staircase), eq. 7 beside it;
  arc:  1.5 eps_A (eq. 9; the first and last chord, see below) + 1.5 cos a + sin a <= sqrt(13)/2
        (the staircase along a chord, its end points rounded against the X motion: X by up to one
        step to the side opposite the staircase's corners, Y by up to 1/2; docs/contours.md); the
        issue's eps_A + 1 step is reported beside it (over / within).
And per arc the unrounded polygon of the 16.16 arithmetic: its inner chords against eps_A (eq. 9
with the first-point correction), its first and last chord against 1.5 eps_A (they join R + eps_A
to a point on the circle), each + 1/16 step for eqs. 15-16's drift and the 16.16 rounding.
Exit 1 if any move exceeds its bound.
"""
import csv
import math
import sys

import contour_ref as ref


# max over a of 1.5 cos a + sin a: the staircase and the rounding of a chord's ends (docs/contours.md)
ARC_STAIRCASE = math.sqrt(13) / 2


def moves(path):
    x = y = 0
    out = []
    for e in path:
        if (e["x"], e["y"]) == (x, y) and e["kind"] not in (3, 4):
            continue
        if e["kind"] in (3, 4):
            r = ref.radius(e, (x, y))
            a0 = math.atan2(y - e["cy"], x - e["cx"])
            a1 = math.atan2(e["y"] - e["cy"], e["x"] - e["cx"])
            s = 1 if e["kind"] == 4 else -1
            sweep = (s * (a1 - a0)) % (2 * math.pi) or 2 * math.pi
            ea = ref.eps_a(e["cr"], r)
            out.append(dict(arc=True, c=(e["cx"], e["cy"]), r=r, a0=a0, s=s, sweep=sweep, cr=e["cr"],
                            p0=(x, y), p1=(e["x"], e["y"]), bound=1.5 * ea + ARC_STAIRCASE,
                            issue=ea + 1.0, poly=ref.polygon_error(e, (x, y), r)))
        else:
            out.append(dict(arc=False, p0=(x, y), p1=(e["x"], e["y"]), bound=ref.staircase(e["x"] - x, e["y"] - y),
                            eq7=ref.eps_l(e["x"] - x, e["y"] - y)))
        x, y = e["x"], e["y"]
    return out


def dist_seg(p, a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    L = dx * dx + dy * dy
    t = 0 if L == 0 else max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L))
    return math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy)


def dist(p, m):
    if not m["arc"]:
        return dist_seg(p, m["p0"], m["p1"])
    cx, cy = m["c"]
    ang = (m["s"] * (math.atan2(p[1] - cy, p[0] - cx) - m["a0"])) % (2 * math.pi)
    if ang <= m["sweep"] + 1e-12:
        return abs(math.hypot(p[0] - cx, p[1] - cy) - m["r"])
    return min(math.dist(p, m["p0"]), math.dist(p, m["p1"]))


def worst_per_move(path, csv_path):
    """The largest distance per move, and how many moves the recording completed."""
    ms = moves(path)
    worst = [0.0] * len(ms)
    i, left, last = 0, False, None
    with open(csv_path) as f:
        for row in csv.DictReader(f):
            p = (int(row["x_count"]), int(row["y_count"]))
            if p == last or i >= len(ms):
                continue
            last = p
            worst[i] = max(worst[i], dist(p, ms[i]))
            if p != ms[i]["p1"]:
                left = True
            elif left:
                i, left = i + 1, False
    return worst, i


def main():
    path = ref.paths(ref.read_hex(sys.argv[1]))[0]
    ms = moves(path)
    worst, i = worst_per_move(path, sys.argv[2])
    bad = 0
    for k, m in enumerate(ms):
        ok = worst[k] <= m["bound"] + 1e-9
        if m["arc"]:
            ea = ref.eps_a(m["cr"], m["r"])
            inner, ends = m["poly"]
            ok = ok and inner <= ea + 1 / 16 and ends <= 1.5 * ea + 1 / 16
            what = (f"arc R {m['r']:.1f} C_R {m['cr']}: polygon {inner:.3f} (ends {ends:.3f}) vs eps_A {ea:.3f}; toolpath "
                    f"{worst[k]:.3f} vs bound {m['bound']:.3f} ({'within' if worst[k] <= m['issue'] else 'over'} "
                    f"eps_A + 1 = {m['issue']:.3f})")
        else:
            what = (f"line {m['p0']}->{m['p1']}: toolpath {worst[k]:.3f} vs staircase bound {m['bound']:.3f} "
                    f"(eq. 7: {m['eq7']:.3f})")
        bad += not ok
        print(f"{'ok ' if ok else 'BAD'} move {k + 1}: {what}")
    if i < len(ms):
        print(f"BAD the recording ends in move {i + 1} of {len(ms)}")
        bad += 1
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
