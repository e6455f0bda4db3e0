import json,glob,collections,statistics,os,sys
parts=['particles-simulate','particles-sort','particles-indirect','particles-light','particles-bin','particles-composite','particles-resolve-behind-glass','particles-resolve','glass-depth']
g=collections.defaultdict(list)
for f in sorted(glob.glob(sys.argv[1]+'/*.json')):
    n=os.path.basename(f)[:-5]; key=n.rsplit('-',1)[0]
    d=json.load(open(f)); p={x['name']:x['median_ms'] for x in d['passes']}
    st=d['technique_stats']
    g[key].append((sum(p.get(k,0) for k in parts),p.get('particles-composite',0),st.get('particle_tile_groups_stopped'),st.get('particle_tile_groups')))
for k,v in g.items():
    print(f"{k:12s} particles {statistics.median(x[0] for x in v):7.2f} composite {statistics.median(x[1] for x in v):7.2f}  stopped {[x[2] for x in v]} groups {v[0][3]}")
