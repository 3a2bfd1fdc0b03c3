# The path rule of docs/thesis.md in Python. The tests (tests/thesis, check_path.py) compare it with
# the thesis-fixed walk-throughs of scripts/thesis; run as a program it checks random lines too:
#   python3 firmware/thesis/check/pathrule.py SEED COUNT MAXCOORD [ALP85]
# (from the repository root; ALP85 defaults to build/bin/alp85): each line is typed into thesis-fixed
# on the emulated board (ideal motors, F 1500), its recording compared step by step with the rule.
import csv, os, random, subprocess, sys, tempfile
def rule(x1,y1,x2,y2):
    dx,dy=x2-x1,y2-y1
    path=[]
    if dx==0:
        y=y1; s=1 if dy>=0 else -1
        while y!=y2: y+=s; path.append(('Y',x1,y))
        return path
    m=(abs(dy)*65536)//abs(dx)          # |M| in 16.16, truncated
    s=(1 if dy>=0 else -1)*(1 if dx>0 else -1)
    sy=1 if dy>=0 else -1; sx=1 if dx>0 else -1
    c=y1 - s*((m*x1)>>16 & 0xFFFF)
    def yid(x):
        if x==x2: return y2
        return (c + s*((m*x)>>16 & 0xFFFF)) & 0xFFFF
    x,y=x1,y1
    while True:
        yi=yid(x)
        if x==x2 and y==yi: break
        if y!=yi: y+=sy; path.append(('Y',x,y))
        else: x+=sx; path.append(('X',x,y))
    return path
def board_path(alp85, x1, y1, x2, y2, work):
    """The steps thesis-fixed makes for the line, from `alp85 script`'s recording at 1 ms."""
    include = os.path.abspath('scripts/include/thesis_start.alp')
    entry = [f'type {" ".join("%04d" % v)}\ntype EXEC' for v in (x1, y1, x2, y2)]
    script = os.path.join(work, 'line.alp')
    with open(script, 'w') as f:
        f.write('\n'.join(['monitor', 'firmware thesis-fixed', 'motor ideal', f'include {include}',
                           'type 0 0 0 0', 'wait display "H1=----" timeout 1s'] +
                          [e + '\nrun 50ms' for e in entry] +
                          ['type 1 5 0 0', 'record line.csv every 1ms', 'press EXEC hold 20ms gap 0ms',
                           'wait display "  8itti" timeout 600s', 'record stop']) + '\n')
    subprocess.run([alp85, 'script', script, '--out-dir', work], check=True, capture_output=True)
    got, px, py = [], 0, 0
    for r in csv.DictReader(open(os.path.join(work, 'line.csv'))):
        x, y = int(r['x_commanded']), int(r['y_commanded'])
        if x != px: got.append(('X', x1 + x, y1 + y))
        if y != py: got.append(('Y', x1 + x, y1 + y))
        px, py = x, y
    return got

def main():
    random.seed(int(sys.argv[1]) if len(sys.argv) > 1 else 1)
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 8
    top = int(sys.argv[3]) if len(sys.argv) > 3 else 60
    alp85 = sys.argv[4] if len(sys.argv) > 4 else 'build/bin/alp85'
    bad = 0
    for _ in range(count):
        x1, y1, x2, y2 = [random.randint(0, top) for _ in range(4)]
        with tempfile.TemporaryDirectory() as work:
            got = board_path(alp85, x1, y1, x2, y2, work)
        exp = rule(x1, y1, x2, y2)
        bad += got != exp
        print((x1, y1, x2, y2), 'OK' if got == exp else 'DIFF', len(got), len(exp))
    print('bad', bad)
    sys.exit(1 if bad else 0)

if __name__ == '__main__':
    main()
