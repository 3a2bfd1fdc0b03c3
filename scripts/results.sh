#!/usr/bin/env bash
# Regenerates docs/results.md and the plots it discusses (docs/img/results-*.svg): the thesis
# firmware's achieved feedrate against the entered one, thesis-fixed, physical motors, in the
# closed loop (feedback scale: the transducers read the scale on the table) and in the emulated
# open loop (feedback commanded: the transducer bits follow the sequencer's commanded steps).
# Usage: bash scripts/results.sh [path/to/alp85]   (default build/bin/alp85)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
alp=${1:-$root/build/bin/alp85}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
python3 - "$alp" "$tmp" "$root" <<'PY'
import csv, subprocess, sys, os, glob
alp, tmp, root = sys.argv[1:4]
img = f'{root}/docs/img'
def pop(x): return bin(x).count('1')
cases = {'X': (0, 50, 100, 50), 'Y': (100, 0, 100, 100), 'diag': (0, 0, 100, 100)}
feeds = [100, 300, 500, 750, 1000, 1300, 1500]
# the plots the text of docs/results.head.md discusses: (loop, line, F)
plots = {('closed', 'diag', 1000), ('closed', 'diag', 750), ('closed', 'X', 300), ('open', 'diag', 1000), ('open', 'Y', 1000)}
# runs that never show Bitti: plotted over a fixed time instead
plot_for = {('closed', 'X', 300): '3s'}
for f in glob.glob(f'{img}/results-*.svg'):
    os.remove(f)

def script(loop, name, f, rec, every, plot, until=None):
    x1, y1, x2, y2 = cases[name]
    L = ['monitor', 'firmware thesis-fixed', 'motor physical',
         'feedback ' + ('scale' if loop == 'closed' else 'commanded'), 'reset',
         'wait display "-ALP 85-" timeout 1s', 'type R 7 0 8 0 0 EXEC',
         'wait display "?.=----" timeout 200ms', 'type 0 0 0 0', 'wait display "H1=----" timeout 200ms']
    for v, nxt in ((x1, 'y1'), (y1, 'H2'), (x2, 'y2'), (y2, 'H')):
        L += [f'type {" ".join("%04d" % v)} EXEC', f'wait display "{nxt}=----" timeout 200ms']
    L += [f'type {" ".join("%04d" % f)}', f'record {rec} every {every}', 'press EXEC hold 20ms gap 0ms',
          f'run {until}' if until else 'wait display "  8itti" timeout 8s', 'run 50ms', 'record stop']
    if plot:
        tag = f'{loop}-{name}_{f}'
        L += [f'plot toolpath {img}/results-{tag}-path.svg', f'plot time {img}/results-{tag}-time.svg']
    path = f'{tmp}/run.alp'
    open(path, 'w').write('\n'.join(L) + '\n')
    return subprocess.run([alp, 'script', path, '--out-dir', tmp], capture_output=True, text=True)

rows = []
for loop in ('closed', 'open'):
    for name, (x1, y1, x2, y2) in cases.items():
        for f in feeds:
            D = 1500 // f
            r = script(loop, name, f, 'm.csv', '1ms', False)
            ok = r.returncode == 0
            data = list(csv.DictReader(open(f'{tmp}/m.csv')))
            moving = [float(d['t_ms']) for i, d in enumerate(data[1:])
                      if d['x_commanded'] != data[i]['x_commanded'] or d['y_commanded'] != data[i]['y_commanded']]
            t = (moving[-1] - moving[0]) if len(moving) > 1 else float('nan')
            last = data[-1]
            dist_mm = ((x2 - x1) ** 2 + (y2 - y1) ** 2) ** 0.5 * 0.05
            # predicted step time (T-states) from the firmware's arithmetic (docs/thesis.md "Timing")
            if name == 'X':   pred = sum(6140 * D + 11393 + 206 * pop(x) for x in range(x1, x2)) / (x2 - x1)
            elif name == 'Y': pred = 6140 * D + 390
            else:             pred = 6140 * D + 12500   # general loop, sloped: about (MULT data-dependent)
            nsteps = abs(x2 - x1) + abs(y2 - y1)
            pred_feed = (0.05 / (pred / 3.072e6)) * 60 * dist_mm / 0.05 / nsteps
            # measured over the n-1 intervals between the first and the last commanded step
            meas_feed = dist_mm * (nsteps - 1) / nsteps / (t / 60000) if t == t and t > 0 else float('nan')
            xt, yt = round(float(last['x_mm']) / 0.05), round(float(last['y_mm']) / 0.05)
            rows.append((loop, name, f, D, pred_feed, meas_feed, 3.072e6 / pred,
                         int(last['x_commanded']), int(last['y_commanded']), xt, yt,
                         int(last['x_lost']), int(last['y_lost']), xt - (x2 - x1), yt - (y2 - y1), ok))
            if (loop, name, f) in plots:
                r = script(loop, name, f, 'p.csv', '10ms', True, plot_for.get((loop, name, f)))
with open(f'{root}/docs/results.md', 'w') as o:
    o.write(open(f'{root}/docs/results.head.md').read())
    o.write('\n| loop | line | F entered | D | F predicted | F measured | steps/s | X cmd | Y cmd | X table | Y table '
            '| X lost | Y lost | X off | Y off | Bitti |\n' + '|---' * 16 + '|\n')
    for r in rows:
        o.write('| {} | {} | {} | {} | {:.0f} | {:.0f} | {:.0f} | {} | {} | {} | {} | {} | {} | {:+d} | {:+d} | {} |\n'
                .format(*r[:15], 'yes' if r[15] else 'no'))
print('\n'.join(str(r) for r in rows))
PY
du -ch "$root"/docs/img/results-* | tail -1
