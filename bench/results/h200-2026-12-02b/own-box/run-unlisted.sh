set -u
source .gpu/setup.sh >/dev/null
E=.gpu/extra
mkdir -p $OUT/r
for rep in 1 2; do
for box in 64 4096 1048576; do
  LLL_RASTER_OWN_BOX=$box $E/lll_old render threel16 --technique lll --width 1920 --height 1080 --frames 100 --out /tmp/a.png --stats $OUT/r/box$box-t16-$rep.json >/dev/null 2>&1 || echo fail $box
  LLL_RASTER_OWN_BOX=$box $E/lll_old render plane --technique lll --width 1920 --height 1080 --frames 100 --out /tmp/a.png --stats $OUT/r/box$box-plane-$rep.json >/dev/null 2>&1 || echo fail $box p
done; done
cd $OUT && python3 - <<'PY'
import json
for sc in ['t16','plane']:
  for box in [64,4096,1048576]:
    v=[]
    for r in (1,2):
      p={x['name']:x['median_ms'] for x in json.load(open(f'r/box{box}-{sc}-{r}.json'))['passes']}
      v.append('vis %.4f bins %.4f res %.4f frame %.4f'%(p['visibility'],p['visibility-bins'],p['visibility-resolve'],p['frame']))
    print(sc,box,' | '.join(v))
PY
tar cf r.tar r && rm -rf r
