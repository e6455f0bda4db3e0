# run2: where vpl-filter's time goes (probe builds of b404e42's filter, not kept): a1 without the
# surface tests, a2 a plain 7x7 tent over both images (no classes, no tests), a3 the centre only;
# old = b404e42. The atrium's 5,144 VPLs at K = 4, lll, 1080p, 15 frames, three repetitions.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2 3; do
for v in old a1 a2 a3; do
  r $v-vpl4-$rep $E/lll_$v atrium --gi vpl-only --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
done; done
for v in a1 a2 a3; do LLL_SHADER_STATS=1 timeout 60 $E/lll_$v render atrium --gi vpl-only --vpl-interleave 4 --technique lll $W --frames 1 --out /tmp/a.png 2>&1 | grep vpl_filter > $OUT/r/$v-shader-stats.txt; done
echo renders done $SECONDS
cd $OUT && tar cJf r.tar.xz r && rm -rf r; ls -la; true
