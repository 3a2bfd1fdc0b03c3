"""Every chord length 1-255 steps on both axes, lines and arcs, by sampling on the emulated board.

  python3 chord_sweep.py ALP85 OUT_DIR [--plan]

A chord of n steps of its major axis u is eq. 5's k = 0 .. n, in segments of 128 (k >> 7); the
master sets up the next chord ahead of the join once this one is in its last segment (RUNJ, JSEG).
At n = 128 that test once failed until the chord's last sample, the set-up then ran in one piece
at the join and the 8155 timer reached its terminal count (TRAP: the monitor's single step).

The G-code programs (written to OUT_DIR, each within the 35 entries of a path table):
  - lines along X and along Y (slope 1/5, alternately up and down: a turn of 0.39 rad, below
    gcode::kCornerRad, so no stop between them), each n = 1..255 once, n = 9 b + r in batch r,
    then 256, 384, 512, 640 (two and more segments), each followed by another line;
  - arcs (G03, the C_R alp85 gcode chooses): chosen by the host model (sampling_ref.py) from
    arcs about phi = 0 (chords along Y) and phi = pi/2 (chords along X) until every n on each axis
    is some arc's chord with a chord after it. Along X an arc chord is at most 249 steps: 250 would
    need C_R 4 at R > 3999 steps with its top inside the Y travel (0-4000 steps, centre >= 0).
Each program runs on the board (alp85 script, ideal motors, 1500 mm/min, recorded every 0.5 ms;
the script from mksampling.py: its end position from the model, no step lost, the run ends in
BITTI, not in the monitor), and check_samples.py compares every sample with the model's and the
toolpath with eq. 7 and eps_A + 1 step (the arcs' times within ARC_LATE_MS of the model's).
--plan: write the programs and check the coverage only.
Exit 1 on any failure.
"""
import concurrent.futures
import math
import os
import subprocess
import sys

import contour_ref as ref
import mksampling
import sampling_ref as S

STEP_MM = 0.05
FEED = 1500
X_ARC_MAX = 249
# Arcs of R below about 20 steps (C_R 1: chords of under 10 steps, fewer samples than the next
# chord's set-up takes in stages) set up every chord at its join, two to three periods of work;
# the grid falls behind by that at each join and catches up in the chords' samples (a sample's own
# work is about half a period): 14.2 ms behind at most in these programs, not the 5.5 ms of chords
# that last the stages.
ARC_LATE_MS = 20.0


def mm(v):
    return f"{v * STEP_MM:.2f}"


def choose_cr(r):
    """gcode::choose_cr: the coarsest C_R with eps_A = 2^(-2 C_R - 4) R <= 1 step."""
    cr = 1
    while math.ldexp(r, -2 * cr - 4) > 1.0:
        cr += 1
    return cr


def arc_entry(start, centre, theta):
    """A CCW arc from the lattice point start about centre through about theta rad, as alp85 gcode
    stores it (the end the lattice point nearest the circle there)."""
    r = math.hypot(start[0] - centre[0], start[1] - centre[1])
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    end = (round(centre[0] + r * math.cos(a0 + theta)), round(centre[1] + r * math.sin(a0 + theta)))
    th = (math.atan2(end[1] - centre[1], end[0] - centre[0]) - a0) % (2 * math.pi)
    cr = choose_cr(r)
    n = math.ceil(th / math.ldexp(1, -cr) - 1e-9) - 1
    return dict(kind=4, cr=cr, feed=FEED, x=end[0], y=end[1], z=0, cx=centre[0], cy=centre[1], n=n)


def joined_chords(entries, start):
    """(kind, axis, n) of each chord that another chord follows without a stop, the entries run
    from start as one group."""
    out, pos, tp, last = [], start, start, None
    for e in entries:
        for a, b in S.chords_of(e, pos, tp):
            c = S.Chord(a, b, tp)
            if last:
                out.append(last)
            last = ("arc" if e["kind"] in (3, 4) else "line", "xy"[c.mu], c.n)
            tp = c.target(c.n)
        pos = (e["x"], e["y"])
    return out


def arc_candidates():
    """Arcs about phi = 0 (centre at Y 2000 steps) and about phi = pi/2 (centre as low as the
    Y travel lets the top stay within 3980 steps), at three start offsets of a chord."""
    out = []
    for r in list(range(2, 200)) + list(range(200, 4097, 5)):
        dphi = math.ldexp(1, -choose_cr(r))
        for off in (0.0, 0.37, 0.71):
            half = min(math.asin(min(1.0, 1900 / r)), math.pi / 4)
            c = (r + 200, 2000)
            a0 = -half + off * dphi
            if half - a0 > dphi:
                st = (round(c[0] + r * math.cos(a0)), round(c[1] + r * math.sin(a0)))
                out.append((st, c, arc_entry(st, c, half - a0)))
            cy = max(0, 3980 - r)
            top = math.pi / 2 if cy + r <= 3980 else math.asin((3980 - cy) / r)
            a0 = math.pi / 4 + off * dphi
            if top - a0 > dphi:
                c = (r + 200, cy)
                st = (round(c[0] + r * math.cos(a0)), round(c[1] + r * math.sin(a0)))
                out.append((st, c, arc_entry(st, c, top - a0)))
    return out


def needed(kind):
    return {(kind, ax, n) for ax in "xy" for n in range(1, 256) if not (kind == "arc" and ax == "x" and n > X_ARC_MAX)}


def arc_plan():
    """Greedy: the arc that covers most lengths still missing per step it takes, until none is."""
    cands = [(st, c, e, set(joined_chords([e], st))) for st, c, e in arc_candidates()]
    need, chosen = needed("arc"), []
    while need:
        best = max(cands, key=lambda k: len(need & k[3]) / (sum(n for _, _, n in k[3]) + 100))
        if not need & best[3]:
            break
        chosen.append(best)
        need -= best[3]
    return sorted(chosen, key=lambda k: k[0])


def line_programs():
    progs = []
    for axis in (0, 1):
        for r in range(9):
            lengths = [n for n in range(1, 256) if n % 9 == r] + [10]
            progs.append((f"lines_{'xy'[axis]}{r}", lengths, axis))
    progs.append(("lines_long", [256, 384, 512, 640, 10], None))
    out = []
    for name, lengths, axis in progs:
        g = [f"(METHOD SAMPLING)", f"(chords: lines of {', '.join(map(str, lengths))} steps)", "G21 G90"]
        axes = (0, 1) if axis is None else (axis,)
        for ax in axes:
            p = [20, 2000] if ax == 0 else [2000, 20]
            g.append(f"G00 X{mm(p[0])} Y{mm(p[1])}")
            for i, n in enumerate(lengths):
                p[ax] += n
                p[1 - ax] += (1 if i % 2 == 0 else -1) * round(n / 5)
                g.append(f"G01 X{mm(p[0])} Y{mm(p[1])}" + (f" F{FEED}" if i == 0 else ""))
        out.append((name, "\n".join(g) + "\n"))
    return out


def arc_programs():
    arcs, out = arc_plan(), []
    for b in range(0, len(arcs), 8):
        g = ["(METHOD SAMPLING)", "(chords: arcs the host model chose, tests/master/chord_sweep.py)", "G21 G90"]
        for st, c, e in ((k[0], k[1], k[2]) for k in arcs[b:b + 8]):
            g.append(f"G00 X{mm(st[0])} Y{mm(st[1])}")
            g.append(f"G03 X{mm(e['x'])} Y{mm(e['y'])} I{mm(c[0] - st[0])} J{mm(c[1] - st[1])} F{FEED}")
        out.append((f"arcs_{b // 8:02d}", "\n".join(g) + "\n"))
    return out


def coverage(hexes):
    """(kind, axis, n) of the chords with a chord after them in the tables' paths, per group."""
    got = set()
    for h in hexes:
        group, start, pos = [], (0, 0), (0, 0)
        for e in ref.paths(ref.read_hex(h))[0] + [dict(kind=S.HEADER)]:
            if e["kind"] == S.HEADER:
                got |= set(joined_chords(group, start))
                group, start = [], pos
                continue
            group.append(e)
            pos = (e["x"], e["y"])
    return got


def main():
    alp85, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    progs = line_programs() + arc_programs()
    hexes = []
    for name, text in progs:
        nc = os.path.join(out, name + ".nc")
        with open(nc, "w") as f:
            f.write(text)
        h = os.path.join(out, name + ".hex")
        subprocess.run([alp85, "gcode", nc, "-o", h], check=True)
        hexes.append(h)
    missing = (needed("line") | needed("arc")) - coverage(hexes)
    if missing:
        print(f"chord_sweep: the programs miss {sorted(missing)}")
        return 1
    print(f"chord_sweep: {len(progs)} programs cover every chord length 1-255 on X and Y, lines and arcs"
          f" (arcs along X to {X_ARC_MAX})")
    if "--plan" in sys.argv:
        return 0
    def run_one(name, h):
        """(report, ok) of one program: its run on the board, then its samples against the model."""
        alp = os.path.join(out, name + ".alp")
        with open(alp, "w") as f:
            f.write(mksampling.script(name, h, name + ".nc"))
        run = subprocess.run([alp85, "script", alp, "--out-dir", out], capture_output=True, text=True)
        if run.returncode != 0:
            return f"{name}: alp85 script failed ({run.returncode}):\n{run.stdout[-2000:]}{run.stderr[-2000:]}", False
        late = ["--late", str(ARC_LATE_MS)] if name.startswith("arcs") else []
        chk = subprocess.run([sys.executable, os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_samples.py"), h,
                              os.path.join(out, name + ".csv")] + late, capture_output=True, text=True)
        report = f"{name}: {chk.stdout.strip().splitlines()[0] if chk.stdout.strip() else ''}"
        if chk.returncode != 0:
            return report + "\n" + chk.stdout[-3000:] + chk.stderr[-2000:], False
        return report, True

    # The programs are independent (each its own files in OUT_DIR): one at a time a core, reported
    # in their order.
    bad = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        results = list(pool.map(lambda p: run_one(p[0][0], p[1]), zip(progs, hexes)))
    for (name, _), (report, ok) in zip(progs, results):
        print(report)
        if not ok:
            bad.append(name)
    if bad:
        print(f"chord_sweep: failed: {' '.join(bad)}")
        return 1
    print("chord_sweep: every program ran to its end and matched the model")
    return 0


if __name__ == "__main__":
    sys.exit(main())
