# Medians over the repetitions of each render (r/VARIANT-SCENARIO-REP.json): lighting = every VPL and
# glass pass after the visibility buffer and lll's fill, ms. Usage: python3 summarize.py RUN_DIR
import json, glob, os, statistics as st, sys
d = sys.argv[1]
L = ['shade-opaque', 'vpl-filter-rows', 'vpl-filter', 'vpl-classes', 'vpl-edges', 'vpl-edges-add', 'vpl-slots-add', 'glass-light',
     'glass']
runs = {}
for f in sorted(glob.glob(os.path.join(d, 'r', '*.json'))):
    runs.setdefault(os.path.basename(f).rsplit('-', 1)[0], []).append(
        {p['name']: p['median_ms'] for p in json.load(open(f))['passes']})
for name, ps in runs.items():
    med = lambda key: st.median([key(p) for p in ps])
    parts = ' '.join('%s %.3f' % (k, med(lambda p: p.get(k, 0))) for k in L if any(k in p for p in ps))
    print('%-16s lighting %.3f  frame %.3f  (n=%d)  %s' % (
        name, med(lambda p: sum(p.get(k, 0) for k in L)), med(lambda p: p['frame']), len(ps), parts))
