# Extracts, per listing line number, the OCR text of Appendix B from the seed (rows split into
# the two columns, numbers taken when plausible, else inferred). Approximate: see RECONSTRUCTION.md.
# Writes /tmp/r/ocr2.json.
import re, json
L=open('/work/shared/seeds/003_bc62744e96698f90.txt',encoding='utf-8').read().split('\n')
pages=[(836,884,0),(887,935,100),(938,985,200),(990,1040,500),(1043,1096,600),(1098,1149,700),(1151,1202,800)]
def clean(t):
    t=re.sub(r'[\*]{2,}|[\.,]{4,}|[,]( ,)+|1{6,}|[:]{5,}|4{6,}|2{6,}','',t)
    t=re.sub(r'(?:^|\s)(?:[,.] ?){3,}',' ',t)
    return re.sub(r'\s+',' ',t).strip()
out={}
def put(n,t,flag):
    if n in out: out[n]=(out[n][0]+' / '+t, out[n][1]+'+dup')
    else: out[n]=(t,flag)
for a,b,base in pages:
    lastL, lastR = base, base+50
    for i in range(a-1,b):
        cells=L[i].split('\t')
        if base==500 and i < 1000: pass
        # split
        cut=None
        for j,c in enumerate(cells[1:],1):
            m=re.match(r'^\s*(\d{2,3})\b',c)
            if m and base+51<=int(m.group(1))<=base+100: cut=j;break
        if cut is None:
            for j,c in enumerate(cells[1:],1):
                if c.strip()=='' and any(x.strip() for x in cells[:j]): cut=j;break
        left=cells[:cut] if cut else cells
        right=cells[cut:] if cut else []
        for part,side in ((left,'L'),(right,'R')):
            txt=' '.join(part).strip()
            if not txt: continue
            if re.search(r'LINE|SOURCE STATE|E STATEMENT|SOURC',txt) and not re.search(r'\b(MOV|LHLD|SHLD|CALL|OUT|SUB|STA|LDA)\b',txt): continue
            lo,hi=(base+1,base+50) if side=='L' else (base+51,base+100)
            m=re.match(r'^\s*(\d{1,3})\s*(?:\d{3}\b)?(.*)$',txt)
            n=None
            if m and lo<=int(m.group(1))<=hi:
                n=int(m.group(1)); rest=m.group(2); flag=''
                prev=lastL if side=='L' else lastR
                if abs(n-(prev+1))>3: flag='(printed %d)'%n; n=prev+1
            else:
                prev=lastL if side=='L' else lastR
                n=prev+1; rest=txt; flag='(no number printed)'
                if n>hi: continue
            if side=='L': lastL=n
            else: lastR=n
            c=clean(rest)
            if c or flag=='': put(n,c,flag)
json.dump(out,open('/tmp/r/ocr2.json','w'),ensure_ascii=False)
for n in range(1,889):
    if 301<=n<=500: continue
    v=out.get(n)
    print(n, v[0] if v else '-', v[1] if v else '')
