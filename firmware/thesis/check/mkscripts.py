# Writes the walk-through scripts scripts/thesis/line_*.alp (thesis-fixed). Every expected value
# comes from the path rule of docs/thesis.md (pathrule.rule) and from the step-time arithmetic
# below (T-states of the listing's instructions, 8085 timings); nothing is taken from the
# emulator. Run from the repository root: python3 firmware/thesis/check/mkscripts.py
import os, sys
sys.path.insert(0, os.path.dirname(__file__))
from pathrule import rule

OUT = 'scripts/thesis'

def pop(x): return bin(x).count('1')

# ---- step times, T-states between two rising pulse edges (docs/thesis.md "Timing") ----------
# DL(A) with its CALL and RET: 3070*A + 25.  DELAY with its CALL: 6140*D + 124.
# General loop, +X on a line with Y1 = Y2 (quadrant code 0, O00 -> O42, |M| = 0, C = Y1 with a
# non-zero low byte), from the edge that brings XAC to x to the next edge:
#   DELAY 6140D+124, OUT's INPUT (X changed, XINC) 18+212, OUT's RET 10, MAIN's INPUT (nothing
#   changed, RZ) 18+122, JMP LOOP 10, CALL YID 18 + YID 10568 + 206*popcount(x) (MULT: 185 +
#   32 passes of 296 - 3 + 40 = 9694, plus 206 per one-bit of the multiplier XAC: JNC not taken,
#   CALL SUM, SUM without carry 191; |M| = 0 so SUM never carries), OKEY (XAC low byte <> X2's)
#   18+42, JZ 7, CALL OUT 18 + 77 + COMPAR 86 + JNZ 7 + MVI/OUT/MVI/MOV/OUT 38
#   = 6140*D + 11393 + 206*popcount(x).
def t_xplus(D, x): return 6140 * D + 11393 + 206 * pop(x)
# ONYP (X1 = X2, Y2 > Y1; thesis-fixed), edge to edge: DELAY 6140D+124, MVI 7, OUT 10, LHLD 16,
#   INX 6, SHLD 16, JMP 10, CALL OKEY 18 + OKEY 142 (XAC = X2, YIDV and YAC share the high
#   byte: all four compares), JZ 7, MVI 7, OUT 10, MVI 7, OUT 10  = 6140*D + 390.
def t_onyp(D): return 6140 * D + 390
# ONYN (Y2 < Y1): two DELAYs 2*(6140D+124), MVI 7, OUT 10, LHLD 16, DCX 6, SHLD 16, JMP 10,
#   CALL OKEY 18 + 142, JZ 7, MVI 7, OUT 10, MVI 7, OUT 10 = 12280*D + 514.
def t_onyn(D): return 12280 * D + 514

def digits(v): return ' '.join('%04d' % v)

def prologue(build, motor, z, x1, y1, x2, y2, f, title):
    L = [f'# {title}', f'# Build {build}, {motor} motors. Entry: docs/thesis.md (four digits in steps of 0.05 mm,',
         '# EXEC accepts); expected path: the rule of docs/thesis.md "How the line is drawn"',
         '# (firmware/thesis/check/pathrule.py), written out by firmware/thesis/check/mkscripts.py.',
         'monitor', f'firmware {build}', f'motor {motor}', 'include ../include/thesis_start.alp',
         f'type {digits(z)}',
         f'# Z = {z}: {z} Z steps at 4 ms, then the X1 prompt',
         'wait display "H1=----" timeout 1s', f'expect axis Z steps {z}', f'expect word ZAC {z}']
    for name, v, nxt in (('H1', x1, 'y1'), ('y1', y1, 'H2'), ('H2', x2, 'y2'), ('y2', y2, 'H')):
        L += [f'type {digits(v)}', f'expect display "{name}={v:04d}"', 'type EXEC',
              f'wait display "{nxt}=----" timeout 200ms']
    D = 1500 // f
    L += [f'type {digits(f)}', f'expect display "H={f:04d}"',
          f'# delay constant D = floor(1500 / {f}) = {D} ms a pulse half', f'expect mem DLYK {D}',
          '# the start key: the display goes blank and the motion begins',
          'expect axis X steps 0', 'expect axis Y steps 0',
          'press EXEC hold 20ms gap 0ms', 'expect display ""']
    return L, D

def ending(x1, y1, x2, y2, z, timeout, physical):
    dx, dy = x2 - x1, y2 - y1
    L = [f'wait display "  8itti" timeout {timeout}',
         f'# the table moved by (X2-X1, Y2-Y1) = ({dx}, {dy}) steps from where it stood',
         f'expect axis X steps {dx}', f'expect axis Y steps {dy}', f'expect axis Z steps {z}',
         f'expect count X {dx}', f'expect count Y {dy}',
         f'expect word XAC {x2}', f'expect word YAC {y2}']
    if physical:
        L += ['expect lost X 0', 'expect lost Y 0', 'expect lost Z 0']
    return L

def checkpoints(x1, y1, x2, y2, nmax=6, skip=4):
    """run until the table reaches chosen positions of the path; the other axis must be there."""
    p = rule(x1, y1, x2, y2)
    L = ['# intermediate points of the rule: when the stepping axis reaches its position, the other',
         '# axis must stand where the rule puts it']
    if len(p) <= skip: return L, p
    idx = list(range(skip, len(p)))
    step = max(1, len(idx) // nmax)
    chosen = idx[::step][:nmax]
    last = {'X': None, 'Y': None}
    for i in chosen:
        a, x, y = p[i]
        # "=" needs the position to be reached for the first time at this event
        key = (a, x if a == 'X' else y)
        if any((b, xx if b == 'X' else yy) == key for b, xx, yy in p[:i]): continue
        v = (x - x1) if a == 'X' else (y - y1)
        o, ov = ('Y', y - y1) if a == 'X' else ('X', x - x1)
        L += [f'run until axis {a} steps = {v} timeout 3s', f'expect axis {o} steps {ov}']
    return L, p

def write(name, lines):
    with open(os.path.join(OUT, name), 'w') as f: f.write('\n'.join(lines) + '\n')

cases = [
    # name, build, motor, z, x1, y1, x2, y2, feed, title, record
    ('line_q1_worked', 'ideal'),
]

def line(name, motor, z, x1, y1, x2, y2, f, title, record=False, extra=None):
    L, D = prologue('thesis-fixed', motor, z, x1, y1, x2, y2, f, title)
    if record:
        L.insert(L.index('press EXEC hold 20ms gap 0ms'), f'record {name}.csv every 1ms')
    c, p = checkpoints(x1, y1, x2, y2)
    if extra: L += extra(D)
    elif motor == 'ideal': L += c
    nsteps = len(p)
    # generous bound: 4*D ms + 5 ms a step (timing is checked exactly elsewhere)
    timeout = max(1, int(nsteps * (4 * D + 5) / 1000) + 1)
    L += ending(x1, y1, x2, y2, z, f'{timeout}s', motor == 'physical')
    if record: L.append('record stop')
    if nsteps == 0: L.remove('expect display ""')
    write(name + '.alp', L)

if __name__ == '__main__':
    line('line_q1_worked', 'physical', 12, 100, 50, 300, 200, 750,
         'The worked session of docs/thesis.md: quadrant 1, shallow (dX 200, dY 150), 750 mm/min.', record=True)
    line('line_q1_steep', 'ideal', 0, 10, 20, 15, 60, 1500, 'Quadrant 1, steep (dX 5, dY 40).', record=True)
    line('line_q2_shallow', 'ideal', 0, 300, 100, 250, 130, 1500, 'Quadrant 2 (dX < 0, dY > 0), shallow.', record=True)
    line('line_q2_steep', 'ideal', 0, 60, 10, 55, 40, 1000, 'Quadrant 2, steep.')
    line('line_q3_shallow', 'physical', 0, 240, 80, 200, 60, 500, 'Quadrant 3 (dX < 0, dY < 0), shallow, physical motors.', record=True)
    line('line_q3_steep', 'ideal', 0, 120, 90, 110, 50, 1500, 'Quadrant 3, steep.')
    line('line_q4_shallow', 'ideal', 0, 40, 100, 90, 80, 1500, 'Quadrant 4 (dX > 0, dY < 0), shallow.', record=True)
    line('line_q4_steep', 'physical', 0, 30, 70, 35, 20, 750, 'Quadrant 4, steep, physical motors.')
    line('line_diag', 'physical', 0, 0, 0, 60, 60, 750, 'The diagonal, physical motors, 750 mm/min (D = 2).', record=True)
    line('line_trunc_split', 'ideal', 0, 5, 10, 8, 11, 1500,
         'Truncation: |M| = 5555H/10000H; YID(7) = 10 + floor(|M|*7) - floor(|M|*5) = 10 + 2 - 1 = 11,\n'
         '# so Y steps at X = 7, where the exact line is at 10.67 (a rule taking the largest whole step\n'
         '# not beyond the ideal Y would step Y at X = 8).', record=True)
    line('line_trunc_end', 'ideal', 0, 0, 0, 3, 1, 1500,
         'Truncation decides the end: |M| = 5555H/10000H, floor(|M|*3) = 0, so without the E7 repair\n'
         '# the motion would end at (3, 0); thesis-fixed sets YID = Y2 at X2 and ends with a Y step at (3, 1).', record=True)
    line('line_wrap', 'ideal', 0, 3276, 0, 3278, 40, 1500,
         'A steep line whose |M|*X passes 65536 (E6): |M| = 20, 20*3276 = 65520, 20*3277 = 65540 -> 4\n'
         '# (mod 65536); YID(3277) = 0 + (4 - 65520) mod 65536 = 20.', record=True)

    def xtiming(D):
        # window from the edge that brings X to 16 to the one that brings it to 48 (x = 16..47)
        tot = sum(t_xplus(D, x) for x in range(16, 48))
        terms = ' + '.join(str(t_xplus(D, x)) for x in range(16, 20))
        return ['# time per step (edge to edge) = 6140*D + 11393 + 206*popcount(XAC) T-states (see',
                '# mkscripts.py for the count); D = %d; from X = 16 to X = 48 the sum over XAC = 16..47 is' % D,
                f'# {terms} + ... = {tot} T-states. The run stops just after the OUT that makes the edge,',
                '# so 30 T before the sum the 48th edge has not come, 10 T after it has.',
                'run until axis X steps = 16 timeout 1s', f'run {tot - 30}t', 'expect axis X steps 47',
                'run 40t', 'expect axis X steps 48']
    line('line_x_plus', 'ideal', 0, 0, 50, 64, 50, 1500, 'X only, +X (Y1 = Y2): the general loop with |M| = 0, and its step time.',
         extra=xtiming)
    line('line_x_minus', 'ideal', 0, 150, 70, 100, 70, 1500, 'X only, -X (Y1 = Y2).', record=True)

    def ytiming(up):
        def f(D):
            t = t_onyp(D) if up else t_onyn(D)
            s = 1 if up else -1
            return [f'# Y-only routine ({"ONYP" if up else "ONYN"}): edge to edge '
                    + ('6140*D + 390' if up else '12280*D + 514') + f' = {t} T-states (D = {D});',
                    f'# 20 steps from Y = {s*5}: {20*t} T-states.',
                    f'run until axis Y steps = {s*5} timeout 1s', f'run {20*t - 30}t', f'expect axis Y steps {s*24}',
                    'run 40t', f'expect axis Y steps {s*25}', 'expect axis X steps 0']
        return f
    line('line_y_up', 'ideal', 0, 100, 100, 100, 130, 1500, 'Y only, up (X1 = X2): the open-loop Y routine ONYP, one DELAY a step.',
         extra=ytiming(True))
    line('line_y_down', 'ideal', 0, 100, 130, 100, 100, 1500, 'Y only, down (X1 = X2): ONYN, two DELAYs a step.',
         extra=ytiming(False))
    line('line_y_up_physical', 'physical', 0, 100, 100, 100, 140, 750,
         'Y only, up, physical motors at 750 mm/min (D = 2: 12670 T = 4.1 ms a step, 242 steps/s: no loss).')
    line('line_zero', 'ideal', 5, 100, 100, 100, 100, 1500, 'Zero length: X1 = X2 and Y1 = Y2: Y-only routine, OKEY ends it at once.')
