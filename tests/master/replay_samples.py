"""Writes the host model's samples (sampling_ref.py) of path 1 of a sampling .hex as pulses on an
exact 2 ms grid, one a line: "seconds axis direction", for machine_calibrate --replay: the run as it
would be if every sample's pulses left on time (docs/results.md, the sampling method at 1500 mm/min).
The Z moves and the timer's restarts at stops are left out (the motors stand still there).

  python3 replay_samples.py PATH.hex OUT.txt
"""
import sys

import contour_ref as ref
import sampling_ref as S


def main():
    path = ref.paths(ref.read_hex(sys.argv[1]))[0]
    run = S.Run(path)
    with open(sys.argv[2], "w") as o:
        for i, (dx, dy) in enumerate(run.samples):
            t = 0.01 + i * 0.002
            if dx:
                o.write("%.6f 0 %d\n" % (t, 1 if dx > 0 else 0))
            if dy:
                o.write("%.6f 1 %d\n" % (t, 1 if dy > 0 else 0))


if __name__ == "__main__":
    main()
