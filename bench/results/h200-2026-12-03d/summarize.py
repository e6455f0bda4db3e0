import json,sys,glob,os,re,statistics
def load(f):
    d=json.load(open(f)); return {p['name']:p['median_ms'] for p in d['passes']}
runs={}
for f in glob.glob('r/*.json'):
    b=os.path.basename(f)[:-5]; v,n,rep=b.split('-')
    runs.setdefault((n,v),[]).append(load(f))
keys=['lll-fill-compute','shade-opaque','vpl-classes','vpl-filter','glass-light','glass','frame']
for (n,v) in sorted(runs):
    rs=runs[(n,v)]
    out=[]
    for k in keys:
        vals=[r[k] for r in rs if k in r]
        if vals: out.append('%s=%s'%(k,'/'.join('%.3f'%x for x in vals)))
    light=[r['shade-opaque']+r.get('vpl-filter',0)+r.get('glass',0)+r.get('glass-light',0)+r.get('vpl-classes',0) for r in rs]
    print('%-10s %-4s'%(n,v),' '.join(out),' lighting=%s'%'/'.join('%.3f'%x for x in light))
