# run8: the visibility rebuild reading each vertex as three vec4s (v4: the working tree of this run)
# against 3bd4ef3 (final2, the same shading as the landed tree): ThreeL's 16 and 256 lights with lll
# and forward at 1080p, `lll render --frames 200 --stats`, two runs; images of threel16 kept.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
bin() { case $1 in v4) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
for rep in 1 2; do for v in final2 v4; do for sc in threel16 threel256; do for t in lll forward; do
  I=/tmp/a.png; [ $rep = 1 ] && [ $sc = threel16 ] && I=$OUT/img/$v-$sc-$t.png
  timeout 40 $(bin $v) render $sc --technique $t $W --frames 200 --stats $OUT/r/$v-$sc-$t-$rep.json --out $I >/dev/null 2>&1 || echo fail $v $sc $t
done; done; done; done
echo renders $SECONDS
cd $OUT && tar cJf r.tar.xz r && tar cf img.tar img && rm -rf r img; ls -la; true
