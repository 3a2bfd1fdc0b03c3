"""The contour example at 1500 mm/min with the ramp, on the physical motors, from the host model's
samples (sampling_ref.py) on an exact 2 ms grid (replay_samples.py, machine_calibrate --replay): what
the sampling method gives a motor when every sample is on time (docs/results.md):

  - each sample's pulses where x* crossed the step (the master's placement): no step lost;
  - each sample's pulses at the sample's start (the 2 ms grid): steps lost, where an axis runs
    between 435 and 495 steps/s (a whole-step jerk every few samples: machine_calibrate --sampled);
  - the placement with each chord's first sample 2.6 ms late (8000 T-states: a join's set-up on
    the master before it was made ahead of the join): steps lost; 1 ms late (3000 T-states): none.
    The master's own run: scripts/master/sampling/contour_1500.alp.

The expected outcomes come from the motor's calibration (docs/machine.md) and the arithmetic of
the grid, not from a run of the master. Exit 1 if any differs.

  python3 feed_replay.py ALP85 MACHINE_CALIBRATE CONTOUR_NORAMP.nc WORKDIR
"""
import os
import re
import subprocess
import sys

import contour_ref as ref
import replay_samples as R

alp85, calibrate, nc, work = sys.argv[1:5]
os.makedirs(work, exist_ok=True)
# the contour with the ramp: contour_1500_noramp.nc without its (RAMP OFF)
text = "".join(l for l in open(nc) if "(RAMP OFF)" not in l)
src, hexf = os.path.join(work, "contour_1500.nc"), os.path.join(work, "contour_1500.hex")
open(src, "w").write(text)
subprocess.run([alp85, "gcode", "--method", "sampling", src, "-o", hexf], check=True)
path = ref.paths(ref.read_hex(hexf))[0]

CASES = [("placed", dict(phase=True), False), ("grid", dict(), True),
         ("placed, joins 1 ms late", dict(phase=True, late_joins=3000), False),
         ("placed, joins 2.6 ms late", dict(phase=True, late_joins=8000), True)]
bad = 0
for name, opts, loses in CASES:
    f = os.path.join(work, "pulses.txt")
    with open(f, "w") as o:
        for t, axis, d in R.pulses(path, **opts):
            o.write("%.6f %d %d\n" % (t, axis, d))
    out = subprocess.run([calibrate, "--replay", f], capture_output=True, text=True, check=True).stdout
    lx, ly = (int(v) for v in re.search(r"lost X (-?\d+), lost Y (-?\d+)", out).groups())
    ok = (lx != 0 or ly != 0) == loses
    bad += not ok
    print(f"{'ok ' if ok else 'BAD'} {name}: lost X {lx}, Y {ly} ({'steps lost' if loses else 'none lost'} expected)")
sys.exit(1 if bad else 0)
