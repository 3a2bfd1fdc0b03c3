"""A small SVG of a master run for docs/contours.md: the true path of path 1 (lines and arcs, red,
dashed) under the recorded toolpath (blue, each position once), in mm.

  python3 plot_svg.py TABLE.hex RECORD.csv OUT.svg
"""
import csv
import sys

import check_path
import contour_ref as ref

MM = ref_mm = 0.05


def main():
    path = ref.paths(ref.read_hex(sys.argv[1]))[0]
    pts, last = [], None
    with open(sys.argv[2]) as f:
        for row in csv.DictReader(f):
            p = (int(row["x_count"]), int(row["y_count"]))
            if p != last:
                pts.append(p)
                last = p
    # keep the corners only: a run of steps along one axis is one line
    keep = [pts[0]]
    for a, b, c in zip(pts, pts[1:], pts[2:]):
        if (b[0] - a[0], b[1] - a[1]) != (c[0] - b[0], c[1] - b[1]):
            keep.append(b)
    pts = keep + [pts[-1]] if len(pts) > 1 else pts
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    x0, x1, y0, y1 = min(xs) - 40, max(xs) + 40, min(ys) - 40, max(ys) + 40
    scale = 600.0 / max(x1 - x0, y1 - y0)
    tx = lambda x: (x - x0) * scale
    ty = lambda y: (y1 - y) * scale
    ideal = []
    for m in check_path.moves(path):
        ideal.append(f"M{tx(m['p0'][0]):.1f},{ty(m['p0'][1]):.1f}")
        if m["arc"]:
            r = m["r"] * scale
            # SVG's y runs down: a CCW arc on the table is clockwise on screen (sweep flag 0)
            big = 1 if m["sweep"] > 3.14159 else 0
            sweep = 0 if m["s"] > 0 else 1
            if m["p0"] == m["p1"]:  # a whole circle: two halves
                c = m["c"]
                mx, my = 2 * c[0] - m["p0"][0], 2 * c[1] - m["p0"][1]
                ideal.append(f"A{r:.1f},{r:.1f} 0 0 {sweep} {tx(mx):.1f},{ty(my):.1f}")
            ideal.append(f"A{r:.1f},{r:.1f} 0 {big} {sweep} {tx(m['p1'][0]):.1f},{ty(m['p1'][1]):.1f}")
        else:
            ideal.append(f"L{tx(m['p1'][0]):.1f},{ty(m['p1'][1]):.1f}")
    w, h = tx(x1), ty(y0)
    poly = " ".join(f"{tx(x):.4g},{ty(y):.4g}" for x, y in pts)
    title = (f"{sys.argv[1].split('/')[-1]}: X {x0 * MM:.0f}-{x1 * MM:.0f} mm, Y {y0 * MM:.0f}-{y1 * MM:.0f} mm")
    with open(sys.argv[3], "w") as o:
        o.write(f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0f}" height="{h + 20:.0f}">\n'
                f'<rect width="100%" height="100%" fill="white"/>\n'
                f'<path d="{" ".join(ideal)}" fill="none" stroke="#c00" stroke-width="3" stroke-dasharray="6 4"/>\n'
                f'<polyline points="{poly}" fill="none" stroke="#06c" stroke-width="1"/>\n'
                f'<text x="4" y="{h + 15:.0f}" font-family="sans-serif" font-size="12">{title}; red: true path, '
                f'blue: recorded toolpath</text>\n</svg>\n')


if __name__ == "__main__":
    main()
