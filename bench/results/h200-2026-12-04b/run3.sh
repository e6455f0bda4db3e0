# run3: vpl-filter-rows + vpl-filter (new: rows summed down columns where the pattern lies on one
# surface, else the gather), against b404e42 (old, the gather everywhere): the atrium's VPLs
# at K = 2, 3, 4, + the atrium's lights, 65,536 VPLs; images at K = 1 to 4; registers per pipeline
# (LLL_SHADER_STATS); the tests on the new tree.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in new) echo .gpu/bin/lll;; old) echo $E/lll_old;; esac; }
W="--width 1920 --height 1080"
for v in new; do LLL_SHADER_STATS=1 timeout 60 $(bin $v) render atrium --gi vpl-only --vpl-interleave 4 --technique lll $W --frames 1 --out /tmp/a.png > $OUT/r/$v-shader-stats.txt 2>&1; done
timeout 60 .gpu/bin/lll render atrium --gi vpl-only --vpl-interleave 1 --technique lll $W --frames 3 --out $OUT/img/new-vpl1.png >/dev/null 2>&1
for rep in 1 2 3; do
for v in new old; do
  B=$(bin $v)
  for k in 2 3 4; do
    img=/tmp/a.png; [ $rep = 1 ] && { [ $v = new ] || [ $k = 4 ]; } && img=$OUT/img/$v-vpl$k.png
    r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $img
  done
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-vplg4-$rep $B atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
done; done
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='InterleavedVpls.*:Gi.*:ComputeGlass.*:ShadingPaths/Analytic.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi \] (atrium)" $OUT/tests.log | head -10
cd $OUT && tar cJf r.tar.xz r tests.log && tar cf img1.tar img && rm -rf r img tests.log; ls -la; true
