"""docs/contours/fig10.csv: the T-states of one 2 ms sample's work (from the sample's output, STOUT,
to the next sample, SSAMP), averaged over 400 samples of a line (X60 Y25 mm, after 150) and 1200 of
a circle (R 20 mm, C_R 3, from its start), at 300, 750, 1200 and 1500 mm/min, measured on the
emulated 8085 with breakpoints (alp85 script); beside them one iteration of the DDA of dda.asm
(which runs every 2 ms whatever the feed: dX / S_r,max at 1500 mm/min).

  python3 fig10_measure.py BUILD_DIR WORKDIR > docs/contours/fig10.csv

docs/contours/fig10.csv is from the master before each sample's pulses were placed where x*
crosses the step: since then STOUT may come after the sample's work (a late pulse), and this
measure would count the wait; the sample's own work is SSMP's (docs/contours.md "The time").
"""
import os
import re
import subprocess
import sys

BUILD, WORK = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
A = os.path.join(BUILD, 'bin', 'alp85')
LST = open(os.path.join(BUILD, 'firmware', 'master', 'master.lst')).read()
def addr(l): return re.search(r'^ +([0-9A-F]{4}) [0-9A-F]+ +[0-9]+ +'+l+r':', LST, re.M).group(1)
STOUT, SSAMP = addr('STOUT'), addr('SSAMP')
def measure(nc_text, name, skip=150, n=400, at='SCHRD'):
    os.makedirs(WORK, exist_ok=True)
    os.chdir(WORK)
    open(f'{name}.nc','w').write(nc_text)
    subprocess.run([A,'gcode',f'{name}.nc','-o',f'{name}.hex'],check=True)
    L=['motor ideal','monitor','firmware thesis-fixed','firmware master',f'load {name}.hex','reset',
       'wait display "-ALP 85-" timeout 1s','type R 7 3 0 0 0 EXEC','wait display "P=-     " timeout 100ms','type 1',
       f'break {at}','type EXEC'] + (['run 60s'] if at != 'SCHRD' else []) + ['delete all','break STOUT','break SSAMP']
    for i in range(2*(skip+n)):
        L+=['run 1s','print time']
    open(f'{name}.alp','w').write('\n'.join(L)+'\n')
    r=subprocess.run([A,'script',f'{name}.alp','--out-dir',os.path.join(WORK,'out')],capture_output=True,text=True)
    toks=re.findall(r'breakpoint ([0-9A-F]+)H|\((\d+) T-states\) since the last', r.stdout+r.stderr)
    ev=[];cur=None
    for a,t in toks:
        if a: cur=a
        else: ev.append((cur,int(t)))
    works=[]
    for (a0,t0),(a1,t1) in zip(ev,ev[1:]):
        if a0==STOUT and a1==SSAMP: works.append(t1-t0)
    w=works[skip:skip+n]
    return sum(w)/len(w), max(w), len(w)
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


if __name__=='__main__':
    d = dda()
    print('feed,line_t,arc_t,dda_t')
    for F in (300,750,1200,1500):
        line = measure(f'(METHOD SAMPLING)\nG21 G90\nG01 X60 Y25 F{F}\n', f'ml{F}')
        arc = measure(f'(METHOD SAMPLING)\nG21 G90\nG00 X70 Y50\nG03 X70 Y50 I-20 J0 F{F}\n', f'ma{F}', skip=5, n=1200, at='SARC')
        print(f'{F},{round(line[0])},{round(arc[0])},{round(d)}')
        print(f'{F}: line max {line[1]}, arc max {arc[1]} T-states', file=sys.stderr)
