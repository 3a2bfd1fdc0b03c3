# Compares the step sequence of a recording (alp85 script's `record FILE.csv`) with the path rule
# of docs/thesis.md (firmware/thesis/check/pathrule.py): python3 check_path.py FILE.csv X1 Y1 X2 Y2.
# The commanded step counts (the sequencers' counts) are read at every sample; the firmware moves
# one axis per step and its steps are milliseconds apart, so at 1 ms sampling each change is one step.
import csv, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), '..', '..', 'firmware', 'thesis', 'check'))
from pathrule import rule
f, x1, y1, x2, y2 = sys.argv[1], *map(int, sys.argv[2:6])
got, px, py = [], 0, 0
for r in csv.DictReader(open(f)):
    x, y = int(r['x_commanded']), int(r['y_commanded'])
    if abs(x - px) + abs(y - py) > 1: sys.exit(f'{f}: two steps between samples at {r["t_ms"]} ms')
    if x != px: got.append(('X', x1 + x, y1 + y))
    if y != py: got.append(('Y', x1 + x, y1 + y))
    px, py = x, y
exp = rule(x1, y1, x2, y2)
if got != exp:
    n = next((i for i, (a, b) in enumerate(zip(got, exp)) if a != b), min(len(got), len(exp)))
    sys.exit(f'{f}: path differs from the rule at step {n}: got {got[n:n+3]}, rule {exp[n:n+3]} ({len(got)} vs {len(exp)} steps)')
print(f'{f}: {len(got)} steps as the rule says')
