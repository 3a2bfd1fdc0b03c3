"""Writes the host model's samples (sampling_ref.py) of path 1 of a sampling .hex as pulses, one a
line: "seconds axis direction", for machine_calibrate --replay: the run as it would be if every
sample's pulses left on time (docs/results.md, the sampling method at 1500 mm/min).
The Z moves and the timer's restarts at stops are left out (the motors stand still there).

  python3 replay_samples.py PATH.hex OUT.txt [--phase] [--quantum T] [--late-joins T]

Without options each sample's pulses leave at its start, on an exact 2 ms grid (the master program
today). --phase: a sample that moves the major axis sends both pulses when x* crosses the step
(sampling_ref.py's phases), the other samples at their start. --quantum T: those times floored to
a multiple of T T-states (a coarser clock). --late-joins T: each chord's first sample T T-states
late (a chord's set-up in the sample before it), the next on time.
"""
import argparse

import contour_ref as ref
import sampling_ref as S

CLOCK = 3.072e6


def pulses(path, phase=False, quantum=1, late_joins=0):
    """(seconds, axis, direction) of every pulse, in time order."""
    run = S.Run(path)
    out = []
    for i, ((dx, dy), ph) in enumerate(zip(run.samples, run.phases)):
        t = 0.01 + i * S.PERIOD / CLOCK
        d = ph // quantum * quantum if phase else 0
        if i in run.joins:
            d = max(d, late_joins)
        t += d / CLOCK
        if dx:
            out.append((t, 0, 1 if dx > 0 else 0))
        if dy:
            out.append((t, 1, 1 if dy > 0 else 0))
    return sorted(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("hex")
    ap.add_argument("out")
    ap.add_argument("--phase", action="store_true")
    ap.add_argument("--quantum", type=int, default=1)
    ap.add_argument("--late-joins", type=int, default=0)
    a = ap.parse_args()
    path = ref.paths(ref.read_hex(a.hex))[0]
    with open(a.out, "w") as o:
        for t, axis, d in pulses(path, a.phase, a.quantum, a.late_joins):
            o.write("%.6f %d %d\n" % (t, axis, d))


if __name__ == "__main__":
    main()
