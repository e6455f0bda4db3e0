import json,glob,collections,statistics,os,sys
L=['shade-opaque','vpl-classes','vpl-filter','glass-light','glass']
P=['particles-simulate','particles-sort','particles-indirect','particles-light','particles-bin','particles-composite','particles-resolve-behind-glass','particles-resolve','glass-depth']
g=collections.defaultdict(list)
for f in sorted(glob.glob(sys.argv[1]+'/*.json')):
    n=os.path.basename(f)[:-5]
    if n.startswith('stall'): continue
    key=n.rsplit('-',1)[0]
    d=json.load(open(f)); p={x['name']:x['median_ms'] for x in d['passes']}
    g[key].append((sum(p.get(k,0) for k in L),p.get('shade-opaque',0),p.get('vpl-filter',0),sum(p.get(k,0) for k in P),p.get('particles-composite',0),p['frame']))
for k,v in sorted(g.items()):
    m=lambda i: statistics.median(x[i] for x in v)
    print(f"{k:14s} lighting {m(0):7.3f} shade {m(1):7.3f} filter {m(2):6.3f} particles {m(3):7.3f} composite {m(4):7.3f} frame {m(5):7.3f}  n={len(v)}")
