import csv,sys,collections
def load(p):
    d=collections.defaultdict(dict)
    for r in csv.DictReader(open(p)):
        d[r['scenario']][r['pass']]=float(r['median_ms'])
    return d
a=load(sys.argv[1]); b=load(sys.argv[2])
parts=['particles-simulate','particles-sort','particles-indirect','particles-light','particles-bin','particles-composite','particles-resolve-behind-glass','particles-draw-behind-glass','particles-resolve','particles-draw','glass-depth']
for s in a:
    pa=sum(v for k,v in a[s].items() if k in parts); pb=sum(v for k,v in b[s].items() if k in parts)
    print(f"{s:48s} particles {pa:8.2f} / {pb:8.2f}  composite {a[s].get('particles-composite',0):8.2f} / {b[s].get('particles-composite',0):8.2f}  bin {a[s].get('particles-bin',0):6.2f}  frame {a[s]['frame']:8.2f} / {b[s]['frame']:8.2f}")
