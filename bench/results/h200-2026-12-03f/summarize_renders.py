# Every particle pass of each render's stats (one settled frame), median over the runs:
# python3 summarize_renders.py FOLDER (files NAME-RUN.json)
import json,glob,collections,statistics,os,sys
P=['particles-simulate','particles-sort','particles-indirect','particles-light','particles-bin','particles-composite','particles-resolve-behind-glass','particles-resolve','glass-depth']
g=collections.defaultdict(list)
for f in sorted(glob.glob(sys.argv[1]+'/*.json')):
    n=os.path.basename(f)[:-5]; key=n.rsplit('-',1)[0]
    d=json.load(open(f)); p={x['name']:x['median_ms'] for x in d['passes']}
    g[key].append((sum(p.get(k,0) for k in P),p.get('particles-light',0),p.get('particles-bin',0),p.get('particles-composite',0),p['frame']))
for k,v in sorted(g.items(), key=lambda kv: (kv[0].split('-',1)[1], kv[0])):
    m=lambda i: statistics.median(x[i] for x in v)
    print(f"{k:26s} particles {m(0):7.3f} light {m(1):6.3f} bin {m(2):6.3f} composite {m(3):7.3f} frame {m(4):7.3f} n={len(v)}")
