# The path rule of docs/thesis.md in Python, checked against thesis-fixed on the emulated board
# with pathcheck.cpp's transducer model: python3 pathrule.py SEED COUNT MAXCOORD (from the repo
# root, /tmp/h/h = pathcheck built as in its header).
import subprocess, random, sys
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
def main():
  random.seed(int(sys.argv[1]) if len(sys.argv)>1 else 1)
  bad=0
  for i in range(int(sys.argv[2]) if len(sys.argv)>2 else 8):
      x1,y1,x2,y2=[random.randint(0,int(sys.argv[3]) if len(sys.argv)>3 else 60) for _ in range(4)]
      out=subprocess.run(['/tmp/h/h','build/firmware/thesis/thesis-fixed.hex','0000']+['%04d'%v for v in (x1,y1,x2,y2)]+['1500','60000'],
          capture_output=True,text=True,env={'PATHLOG':'1'}).stdout.split('\n')
      got=[(l.split()[0],int(l.split()[1]),int(l.split()[2])) for l in out if l[:1] in 'XY' and len(l.split())==3]
      exp=rule(x1,y1,x2,y2)
      ok = got==exp
      bad+= not ok
      print((x1,y1,x2,y2), 'OK' if ok else 'DIFF', len(got), len(exp), out[-2][:60] if not ok else '')
  print('bad',bad)

if __name__ == '__main__':
    main()
