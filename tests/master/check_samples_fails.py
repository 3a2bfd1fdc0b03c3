"""check_samples.py can fail: it must refuse a recording where one sample's X pulse comes one
sample later than the model says (the recorded commanded X held back by one step for 2 ms), and
one where every other moving sample's pulses come 1 ms late (the pulses not where the model places
them in their samples, with the same outputs in the same order).

  python3 check_samples_fails.py TABLE.hex RECORD.csv WORKDIR
"""
import csv
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
hexf, rec, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
rows = list(csv.DictReader(open(rec)))
# the 500th row where X moves: hold its commanded X back for four rows (2 ms)
moves = [i for i in range(1, len(rows)) if rows[i]["x_commanded"] != rows[i - 1]["x_commanded"]]
k = moves[500]
old = rows[k - 1]["x_commanded"]
for i in range(k, k + 4):
    rows[i]["x_commanded"] = old
bad = os.path.join(work, "moved.csv")
with open(bad, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=rows[0].keys())
    w.writeheader()
    w.writerows(rows)
# every other moving row's change 1 ms (two rows) later, where the next change is further off
rows = list(csv.DictReader(open(rec)))
keys = ("x_commanded", "y_commanded")
changes = [i for i in range(1, len(rows)) if any(rows[i][k] != rows[i - 1][k] for k in keys)]
for n, (i, nxt) in enumerate(zip(changes, changes[1:])):
    if n % 2 == 0 and nxt - i > 3:
        for j in (i, i + 1):
            for k in keys:
                rows[j][k] = rows[i - 1][k]
late = os.path.join(work, "late.csv")
with open(late, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=rows[0].keys())
    w.writeheader()
    w.writerows(rows)
check = [sys.executable, os.path.join(here, "check_samples.py"), hexf]
good = subprocess.run(check + [rec]).returncode
refused = subprocess.run(check + [bad]).returncode
refused_late = subprocess.run(check + [late]).returncode
print(f"the recording: status {good}; with one pulse moved: status {refused}; every other 1 ms late: status {refused_late}")
sys.exit(0 if good == 0 and refused == 1 and refused_late == 1 else 1)
