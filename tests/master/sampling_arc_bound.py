"""Sampling arcs against eps_A + 1 step, checked exhaustively over every integer radius the master
takes (docs/contours.md, "Every arc is within eps_A + 1 step"), not argued.

  python3 sampling_arc_bound.py [R_MAX] [--less D]

--less D: hold the targets to eps_A + 1 - D instead (CTest master:sampling-arc-bound-can-fail: at
R_MAX 300 and D 0.1 it must fail, R 64 standing 0.097 step inside).

The argument "the chord's positions are round(T_y x + y0*), 1/2 cos(alpha) from the chord, and the
chord eps_A (1.5 eps_A for the first and last) from the arc" gives 1.5 eps_A + 1/2 plus small terms
at the first and last chords: at eps_A = 1 that is 2.0 and more, not below eps_A + 1. So every
circle is worked here instead: for every integer radius R = 2 .. R_MAX steps (4096: C_R 1-4, all
that alp85 gcode chooses for R up to 204.8 mm), at the C_R alp85 gcode chooses (the coarsest with
eps_A = 2^(-2 C_R - 4) R <= 1), the full circle from (R, 0) about the centre, counter-clockwise and
clockwise, its chords between the master's exact 16.16 vertices (contour_ref.polygon_fixed) and
each sample's target on them (sampling_ref.Chord.target, eq. 5: with a feed of at most one step a
sample the tool stands on each target in turn).

Each chord is first bounded without its targets: every target p_k lies within 1/2 + D of the
point c_k of the chord's line at the same u (the rounding, and D the largest difference between
the 8085's Y_i* + T_y x_r and the exact line, which is linear within each 128-step segment, so its
largest is at a segment's ends), and c_k within [min |c| - R, max |c| - R] of the circle (|c| is
convex along the line: its largest at the ends, its least at the foot of the perpendicular). A chord
whose bound is within eps_A + 1 needs no more; every other chord's targets are measured one by one.
Prints, per C_R, the least margin of a measured chord, and exits 1 if any target stands farther than eps_A + 1 from its
circle. Not covered: radii that are not whole steps (start points off the axes), arcs whose end is
not their start (their last chord ends on a lattice point up to a step off the circle), and C_R 5
and up (radii over 4096 steps, arcs only partly on the table).
"""
import math
import sys

import contour_ref as ref
import sampling_ref as S


def choose_cr(r):
    """gcode::choose_cr."""
    cr = 1
    while math.ldexp(r, -2 * cr - 4) > 1.0:
        cr += 1
    return cr


def chord_bound(c, a, e, centre, r):
    """An upper bound of |p_k| - R and R - |p_k| over the chord's targets, without them."""
    mu, mv = c.mu, 1 - c.mu
    au, av = a[mu] / 65536.0, a[mv] / 65536.0
    eu, ev = e[mu] / 65536.0, e[mv] / 65536.0
    slope = (ev - av) / (eu - au) if eu != au else 0.0

    def vline(u):
        return av + slope * (u - au)

    # D: the 8085's value before rounding, Y_i* + T_y x_r (in steps from P_v, signed by sigma),
    # against the exact line, at each segment's first and last step
    d = 0.0
    for i in range(c.n // 128 + 1):
        for k in (128 * i, min(128 * i + 127, c.n)):
            if k > c.n:
                continue
            yf = (c.y0 + i * c.yd + c.t * (k & 127)) / 65536.0
            u = c.p[mu] + c.su * k
            exact = c.sigma * (vline(u) - c.p[mv])
            d = max(d, abs(yf - exact))
    # |c| along the line from u_0 to u_n: largest at an end, least at the foot of the perpendicular
    u0, un = c.p[mu], c.p[mu] + c.su * c.n
    cu, cv = centre[mu], centre[mv]

    def rad(u):
        return math.hypot(u - cu, vline(u) - cv)

    ends = [rad(u0), rad(un)]
    foot = (cu + slope * (cv - av) + slope * slope * au) / (1 + slope * slope)
    lo = min(ends + ([rad(foot)] if min(u0, un) <= foot <= max(u0, un) else []))
    return max(max(ends) - r, r - lo) + 0.5 + d


def circle(r, ccw, less=0.0, centre=(8192, 8192)):
    """The largest distance from the circle of the targets of the chords whose bound is not within
    eps_A + 1 (the others are within it), and how many such chords there were."""
    k = choose_cr(r)
    start = (centre[0] + r, centre[1])
    n = math.ceil(2 * math.pi * 2 ** k - 1e-9) - 1
    e = dict(kind=4 if ccw else 3, cr=k, feed=1500, x=start[0], y=start[1], z=0, cx=centre[0], cy=centre[1], n=n)
    bound = ref.eps_a(k, r) + 1.0 - less
    worst, measured, tp = 0.0, 0, start
    for a, b in S.chords_of(e, start, tp):
        c = S.Chord(a, b, tp)
        if chord_bound(c, a, b, centre, r) > bound:
            measured += 1
            for kk in range(c.n + 1):
                p = c.target(kk)
                worst = max(worst, abs(math.hypot(p[0] - centre[0], p[1] - centre[1]) - r))
        tp = c.target(c.n)
    return k, bound, worst, measured


def main():
    args = sys.argv[1:]
    less = 0.0
    if "--less" in args:
        i = args.index("--less")
        less = float(args[i + 1])
        del args[i:i + 2]
    rmax = int(args[0]) if args else 4096
    per = {}
    bad = []
    for r in range(2, rmax + 1):
        for ccw in (True, False):
            k, bound, worst, measured = circle(r, ccw, less)
            m = per.setdefault(k, [0, 0, 0, None])
            m[0] += 1
            m[1] += measured
            if measured and (m[3] is None or bound - worst < m[3][0]):
                m[3] = (bound - worst, r, ccw, worst, bound)
            if worst > bound + 1e-9:
                bad.append((r, ccw, k, worst, bound))
    for k in sorted(per):
        circles, measured, _, least = per[k]
        if least is None:
            print(f"C_R {k}: {circles} circles, every chord within eps_A + 1 by its bound")
            continue
        margin, r, ccw, worst, bound = least
        print(f"C_R {k}: {circles} circles, {measured} chords measured target by target; the least margin "
              f"R {r} {'CCW' if ccw else 'CW'}: {worst:.3f} of eps_A + 1 = {bound:.3f} ({margin:.3f} step inside)")
    for r, ccw, k, worst, bound in bad[:20]:
        print(f"BAD R {r} {'CCW' if ccw else 'CW'} C_R {k}: a target {worst:.3f} from the circle, eps_A + 1 = {bound:.3f}")
    if bad:
        print(f"{len(bad)} circles stand farther than eps_A + 1")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
