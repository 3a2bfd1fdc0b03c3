"""check_samples.py can fail: it must refuse a recording where one sample's X pulse comes one
sample later than the model says (the recorded commanded X held back by one step for 2 ms).

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
good = subprocess.run([sys.executable, os.path.join(here, "check_samples.py"), hexf, rec]).returncode
refused = subprocess.run([sys.executable, os.path.join(here, "check_samples.py"), hexf, bad]).returncode
print(f"the recording: status {good}; with one pulse moved: status {refused}")
sys.exit(0 if good == 0 and refused == 1 else 1)
