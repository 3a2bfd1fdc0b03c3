"""The best any rounding of the paper's vertices can do with the thesis line routine: for a full
circle (centre 2000, 2000; start on +X) at a given C_R, each vertex of eq. 11 (first-point
correction included) may go to any of the 16 lattice points around it (its floor and ceiling in X
and Y, and one step beyond either: every rounding, bias or radial shift of up to a step); the
chords between them are drawn by the thesis rule (firmware/thesis/check/pathrule.py). Dynamic
programming over the vertices minimises the largest distance of any tool position from the circle
exactly (a chord's cost depends only on its two ends).

  python3 best_rounding.py R_STEPS C_R [--over]

prints that least possible largest error beside eps_A + 1; with --over, exit 1 unless it exceeds
eps_A + 1 (the bound is out of reach for every choice of end points: docs/contours.md).
"""
import math
import os
import sys

import contour_ref as ref

sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../firmware/thesis/check"))
from pathrule import rule  # noqa: E402


def vertices(r, k):
    """The unrounded vertices (16.16, relative to the centre) of a CCW full circle from (r, 0)."""
    e = dict(kind=4, cr=k, x=r, y=0, cx=0, cy=0, n=math.ceil(2 * math.pi * 2 ** k - 1e-9) - 1)
    return [(round(x * 65536), round(y * 65536)) for x, y in ref.polygon(e, (r, 0))[1:-1]]


C = 2000  # the centre, X and Y: the line routine's coordinates are unsigned


def chord_error(p, q, r):
    return max((abs(math.hypot(x - C, y - C) - r) for _, x, y in rule(p[0], p[1], q[0], q[1])), default=0.0)


def best(r, k):
    start = (C + r, C)
    layers = []
    for ax, ay in vertices(r, k):
        fx, fy = C + (ax >> 16), C + (ay >> 16)
        layers.append([(fx + i, fy + j) for i in (-1, 0, 1, 2) for j in (-1, 0, 1, 2)])
    layers.append([start])
    cost = {start: 0.0}
    for layer in layers:
        cost = {q: min(max(c, chord_error(p, q, r)) for p, c in cost.items()) for q in layer}
    return cost[start]


def main():
    r, k = int(sys.argv[1]), int(sys.argv[2])
    b = best(r, k)
    bound = ref.eps_a(k, r) + 1
    print(f"R {r} steps, C_R {k}: the best choice of end points leaves {b:.3f} steps; eps_A + 1 = {bound:.3f}")
    if "--over" in sys.argv:
        sys.exit(0 if b > bound else 1)


if __name__ == "__main__":
    main()
