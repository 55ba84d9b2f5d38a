#!/usr/bin/env python3
# Punch 3 holes (radius R x diagonal) into a closed mesh and fold their borders: every 3rd border
# vertex is moved away from its hole's centre by 1.5 x the mean edge length (scan-like folds).
import sys, math, random
def read_off(p):
    t=open(p).read().split('\n'); t=[l for l in t if l.strip() and not l.startswith('#')]
    hdr=t[0].strip(); i=1
    if hdr!='OFF': 
        parts=hdr[3:].split(); nv,nf=int(parts[0]),int(parts[1]); i=1
    else:
        nv,nf,_=map(int,t[1].split()[:3]); i=2
    V=[list(map(float,t[i+k].split()[:3])) for k in range(nv)]
    F=[list(map(int,t[i+nv+k].split()[1:4])) for k in range(nf)]
    return V,F
src,out,R,seed=sys.argv[1],sys.argv[2],float(sys.argv[3]),int(sys.argv[4])
V,F=read_off(src); random.seed(seed)
lo=[min(v[k] for v in V) for k in range(3)]; hi=[max(v[k] for v in V) for k in range(3)]
diag=math.dist(lo,hi); r=R*diag
el=sum(math.dist(V[f[0]],V[f[1]]) for f in F[:2000])/min(len(F),2000)
centers=[V[random.randrange(len(V))] for _ in range(3)]
keep=[f for f in F if all(min(math.dist(V[v],c) for c in centers)>r for v in f)]
# border vertices: edges used once
from collections import Counter, defaultdict
cnt=Counter(); nxt={}
for f in keep:
    for a,b in ((f[0],f[1]),(f[1],f[2]),(f[2],f[0])): cnt[(min(a,b),max(a,b))]+=1; nxt[(a,b)]=1
border=set()
for f in keep:
    for a,b in ((f[0],f[1]),(f[1],f[2]),(f[2],f[0])):
        if cnt[(min(a,b),max(a,b))]==1: border.add(a); border.add(b)
moved=0
for k,v in enumerate(sorted(border)):
    if k%3: continue
    c=min(centers,key=lambda c:math.dist(V[v],c)); d=[V[v][i]-c[i] for i in range(3)]; n=math.sqrt(sum(x*x for x in d)) or 1
    V[v]=[V[v][i]+1.5*el*d[i]/n for i in range(3)]; moved+=1
used=sorted({v for f in keep for v in f}); idx={v:i for i,v in enumerate(used)}
with open(out,'w') as o:
    o.write('OFF\n%d %d 0\n'%(len(used),len(keep)))
    for v in used: o.write('%.17g %.17g %.17g\n'%tuple(V[v]))
    for f in keep: o.write('3 %d %d %d\n'%tuple(idx[x] for x in f))
print(out, len(F)-len(keep),'faces removed', moved,'border vertices moved')
