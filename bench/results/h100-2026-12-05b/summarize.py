import json,glob,statistics,sys,os,collections
d=collections.defaultdict(lambda: collections.defaultdict(list))
for f in glob.glob(sys.argv[1]+'/*.json'):
    n=os.path.basename(f)[:-5]; v,rest=n.split('-',1); case=rest.rsplit('-',1)[0]
    j=json.load(open(f)); p={x['name']:x['median_ms'] for x in j['passes']}
    d[case][v].append((p.get('shade-opaque',float('nan')),p['frame'], j.get('validation_messages')))
vs=sys.argv[2].split()
print('| case | '+' | '.join(vs)+' |')
for c in sorted(d):
    row=[]
    for v in vs:
        x=d[c][v]
        if not x: row.append('-'); continue
        row.append('%.4f (%.4f)'%(statistics.median(a for a,_,_ in x),statistics.median(b for _,b,_ in x)))
    print('| '+c+' | '+' | '.join(row)+' |')
