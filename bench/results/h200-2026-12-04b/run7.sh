# run7: vpl-filter by class rows (new: each class row whose rows vpl-filter-rows summed whole and on
# the pixel's surface takes their sums, the others gather class by class) against 31a1d16 (sep: the
# rows only where the whole pattern is on the surface, else the gather): the atrium's VPLs at K = 3,
# 4, 65,536 VPLs, + the atrium's lights; images at K = 4; the interleaving and GI tests.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in new) echo .gpu/bin/lll;; sep) echo $E/lll_sep;; esac; }
W="--width 1920 --height 1080"
for rep in 1 2 3; do
for v in new sep; do
  B=$(bin $v)
  for k in 3 4; do
    img=/tmp/a.png; [ $rep = 1 ] && [ $k = 4 ] && img=$OUT/img/$v-vpl$k.png
    r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $img
  done
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-vplg4-$rep $B atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
done; done
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='InterleavedVpls.*:Gi.*:GiReference.*:ComputeGlass.*:ShadingPaths/Analytic.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi \] (atrium)" $OUT/tests.log | head -10
cd $OUT && tar cJf r.tar.xz r tests.log && tar cf img1.tar img && rm -rf r img tests.log; ls -la; true
