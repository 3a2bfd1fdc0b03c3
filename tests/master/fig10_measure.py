"""docs/contours/fig10.csv: the ALP 85's counterpart of Fig. 10, the 8085's T-states in a 2 ms sample
(6144) taken by the sampling method's whole sample (the timer, the ramp, eqs. 4-6, the pulse's
placement and OUT: more than the paper's "interpolation"), measured on the emulated master (firmware/master/master.asm) with breakpoints
(alp85 script), over 400 samples of a line (X60 Y25 mm, after its first 150) and 1200 of a circle
(R 20 mm, C_R 3, from its 5th), at 300, 750, 1200 and 1500 mm/min; beside them one iteration of
the bare DDA line loop of dda.asm (two 16-bit additions and one OUT: no timer, ramp or arcs; it
runs every 2 ms whatever the feed: dX / S_r,max at 1500 mm/min). Not the paper's comparison: its
Koren DDA and Middleditch method are not implemented.

A sample runs from its tick (STICK's poll of the timer ending: the CALL TRWP after STK0's loop; or
GRD, where a set-up at a join took the tick) to the next tick. In it:
  - the wait for the tick: from STICK's entry to the tick (the CPU idle, polling);
  - the wait for the pulse's place: WOUT's 20-T-state loop (from its LXI D,-20 to its JMP STOUT),
    where the CPU idles until the counter reaches the moment x* crosses the faster axis's step;
  - the look-ahead jobs: each CALL of RUNJ (a stage of the next vertex or the next chord's set-up,
    run in the spare time of the samples before the join), from RUNJ's entry to its return;
  - the rest is the sample's own work: the tick's rewind, the ramp, eqs. 4-6, the pulse's output
    and placement arithmetic, and at a chord's end the join (the copy of the set-up made ahead, or
    the set-up itself when it could not be made ahead) and the next vertex when it was not ready.
Columns (T-states a sample, averaged, unless _max): feed (mm/min); line_sample, line_sample_jobs
(the sample's whole work, and it + jobs), arc_sample, arc_sample_jobs; bare_dda_line (one iteration
of dda.asm); the largest of each, line_sample_max, line_sample_jobs_max, arc_sample_max,
arc_sample_jobs_max; line_place, arc_place: the
placement's arithmetic within the sample work, the crossing's division (SSMP, from its LHLD KST
after eq. 4 to the XRA A after SHLD PDN) and WOUT up to its wait or its output (the counter's read
and rewind): the pulse's place, which on the paper's machine its software servo takes care of
(docs/contours.md). A summary of each run (the waits, the 95th percentile) goes to
standard error.

  python3 fig10_measure.py BUILD_DIR WORKDIR > docs/contours/fig10.csv
"""
import os
import re
import subprocess
import sys

if len(sys.argv) != 3:
    raise SystemExit('usage: python3 fig10_measure.py BUILD_DIR WORKDIR > docs/contours/fig10.csv')
BUILD, WORK = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
for need in ('bin/alp85', 'firmware/master/master.lst'):
    if not os.path.isfile(os.path.join(BUILD, need)):
        raise SystemExit(f'fig10_measure.py: {os.path.join(BUILD, need)} missing: build alp85 first')
A = os.path.join(BUILD, 'bin', 'alp85')
LST = open(os.path.join(BUILD, 'firmware', 'master', 'master.lst')).read().splitlines()


def addr(pattern, after=0, start='0000'):
    """The address of the first listing line at or after start whose source matches pattern, plus after."""
    for ln in LST:
        m = re.match(r' +([0-9A-F]{4}) [0-9A-F]+ +[0-9]+ +(.*)$', ln)
        if m and int(m.group(1), 16) >= int(start, 16) and re.match(pattern, m.group(2)):
            return '%04X' % (int(m.group(1), 16) + after)
    raise SystemExit(f'fig10_measure.py: {pattern!r} not in master.lst')


def addrs(pattern, after=0):
    out = []
    for ln in LST:
        m = re.match(r' +([0-9A-F]{4}) [0-9A-F]+ +[0-9]+ +(.*)$', ln)
        if m and re.match(pattern, m.group(2)):
            out.append('%04X' % (int(m.group(1), 16) + after))
    return out


STICK = addr(r'STICK:')
TICK = addr(r'CALL\s+TRWP')            # STK0's poll ended: the tick
GRD = addr(r'GRD:')
W0 = addr(r'LXI\s+D,-20\b')            # WOUT's wait loop starts
W1 = addr(r'WO1:', 4)                     # ... and ends (its JMP STOUT)
RUNJ = addr(r'RUNJ:')
WOUT, STOUT = addr(r'WOUT:'), addr(r'STOUT:')
DIV0 = addr(r'LHLD\s+KST\s+; x\* crossed')      # the crossing's division ...
DIV1 = addr(r'SHLD\s+PDN', 3, start=addr(r'PD4:'))  # ... to its XRA A after SHLD PDN
RUNJ_RET = addrs(r'(\w+:\s+)?C(ALL|NZ)\s+RUNJ\b', 3)


def measure(nc_text, name, skip=150, n=400, at='SCHRD'):
    os.makedirs(WORK, exist_ok=True)
    os.chdir(WORK)
    open(f'{name}.nc', 'w').write(nc_text)
    subprocess.run([A, 'gcode', f'{name}.nc', '-o', f'{name}.hex'], check=True)
    L = ['motor ideal', 'monitor', 'firmware thesis-fixed', 'firmware master', f'load {name}.hex', 'reset',
         'wait display "-ALP 85-" timeout 1s', 'type R 7 3 0 0 0 EXEC', 'wait display "P=-     " timeout 100ms', 'type 1',
         f'break {at}', 'type EXEC'] + (['run 60s'] if at != 'SCHRD' else []) + ['delete all']
    L += [f'break 0{a}H' for a in [STICK, TICK, GRD, W0, W1, RUNJ, WOUT, STOUT, DIV0, DIV1] + RUNJ_RET]
    # each sample: STICK, its tick, and when they come the division (2), WOUT and its wait (3),
    # the output, a job (2)
    for i in range(10 * (skip + n + 2)):
        L += ['run 1s', 'print time']
    open(f'{name}.alp', 'w').write('\n'.join(L) + '\n')
    r = subprocess.run([A, 'script', '-v', f'{name}.alp', '--out-dir', os.path.join(WORK, 'out')], capture_output=True, text=True)
    toks = re.findall(r'breakpoint ([0-9A-F]+)H|\((\d+) T-states\) since the last reset', r.stdout + r.stderr)
    ev = []
    cur = None
    for a, t in toks:
        if a:
            cur = a
        elif cur:
            ev.append((cur, int(t)))
            cur = None
    ticks = [i for i, (a, _) in enumerate(ev) if a in (TICK, GRD)]
    work, total, period, pwait, place = [], [], [], [], []
    for i0, i1 in zip(ticks, ticks[1:]):
        t0, t1 = ev[i0][1], ev[i1][1]
        end, wait, jobs, w_at, j_at, pl, p_at = t1, 0, 0, None, None, 0, None
        for a, t in ev[i0 + 1:i1]:
            if a == STICK:
                end = t
            elif a in (DIV0, WOUT):
                p_at = t
            elif a in (DIV1, STOUT) and p_at is not None:
                pl += t - p_at
                p_at = None
            elif a == W0:
                if p_at is not None:
                    pl += t - p_at
                    p_at = None
                w_at = t
            elif a == W1 and w_at is not None:
                wait += t - w_at
                w_at = None
            elif a == RUNJ:
                j_at = t
            elif a in RUNJ_RET and j_at is not None:
                jobs += t - j_at
                j_at = None
        busy = end - t0 - wait
        work.append(busy - jobs)
        total.append(busy)
        period.append(t1 - t0)
        pwait.append(wait)
        place.append(pl)
    w, tt = work[skip:skip + n], total[skip:skip + n]
    if len(w) < n:
        raise SystemExit(f'fig10_measure.py: {name}: {len(w)} samples measured, {n} wanted')
    p, pw, pp = period[skip:skip + n], pwait[skip:skip + n], place[skip:skip + n]
    print(f'{name}: {n} samples, tick to tick {sum(p) / n:.0f} T-states on average; work {sum(w) / n:.0f}, '
          f'jobs {(sum(tt) - sum(w)) / n:.0f}, the pulse\'s wait {sum(pw) / n:.0f}, the tick\'s wait '
          f'{(sum(p) - sum(tt) - sum(pw)) / n:.0f}; work 95 % below {sorted(w)[int(0.95 * n)]}; the placement\'s '
          f'arithmetic {sum(pp) / n:.0f}', file=sys.stderr)
    return sum(w) / n, max(w), sum(tt) / n, max(tt), sum(pp) / n


def dda():
    """T-states of one iteration of tests/master/dda.asm, averaged over its 100."""
    os.makedirs(WORK, exist_ok=True)
    asm = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'dda.asm')
    open(os.path.join(WORK, 'dda.alp'), 'w').write(
        f'motor ideal\nmonitor\nload {asm}\nset reg PC DDA\nrun until DIT timeout 1s\nmark\n'
        'run until DDONE timeout 1s\nprint time\n')
    r = subprocess.run([A, 'script', os.path.join(WORK, 'dda.alp'), '--out-dir', os.path.join(WORK, 'out')],
                       capture_output=True, text=True)
    return int(re.search(r'\((\d+) T-states\) since the mark', r.stdout).group(1)) / 100


if __name__ == '__main__':
    d = dda()
    print('feed,line_sample,line_sample_jobs,arc_sample,arc_sample_jobs,bare_dda_line,line_sample_max,'
          'line_sample_jobs_max,arc_sample_max,arc_sample_jobs_max,line_place,arc_place')
    for F in (300, 750, 1200, 1500):
        ln = measure(f'(METHOD SAMPLING)\nG21 G90\nG01 X60 Y25 F{F}\n', f'ml{F}')
        ar = measure(f'(METHOD SAMPLING)\nG21 G90\nG00 X70 Y50\nG03 X70 Y50 I-20 J0 F{F}\n', f'ma{F}', skip=5, n=1200, at='SARC')
        print(f'{F},{round(ln[0])},{round(ln[2])},{round(ar[0])},{round(ar[2])},{round(d)},'
              f'{ln[1]},{ln[3]},{ar[1]},{ar[3]},{round(ln[4])},{round(ar[4])}', flush=True)
