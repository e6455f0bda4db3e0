import json,glob,collections,statistics,os,sys
P=['particles-simulate','particles-sort','particles-indirect','particles-light','particles-bin','particles-composite','particles-resolve-behind-glass','particles-resolve','glass-depth']
g=collections.defaultdict(list)
for f in sorted(glob.glob(sys.argv[1]+'/*.json')):
    n=os.path.basename(f)[:-5]
    key=n.rsplit('-',1)[0]
    d=json.load(open(f)); p={x['name']:x['median_ms'] for x in d['passes']}
    t=d['technique_stats']
    g[key].append((sum(p.get(k,0) for k in P),p.get('particles-bin',0),p.get('particles-composite',0),p['frame'],t.get('particle_tile_entries_culled',-1),t.get('particle_tile_entries_used',0),t.get('particle_tile_groups_stopped',0)))
for k,v in sorted(g.items()):
    m=lambda i: statistics.median(x[i] for x in v)
    print(f"{k:14s} particles {m(0):7.3f} bin {m(1):6.3f} composite {m(2):7.3f} frame {m(3):7.3f} culled {m(4):10.0f} used {m(5):10.0f} stopped {m(6):6.0f} n={len(v)}")
