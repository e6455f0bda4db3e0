# run2: vpl-filter reading one 16-byte texel a sample (1d32d20, new) against 73138b9 (old, the
# widened lobes): the atrium's VPLs at K = 2, 3, 4, + the atrium's lights, 65,536 VPLs; images at
# K = 3, 4; the interleaving, GI and compute-glass tests on the GPU with validation.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_old; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2 3; do
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  for k in 2 3 4; do
    img=/tmp/a.png; [ $rep = 1 ] && [ $k != 2 ] && img=$OUT/img/$v-vpl$k.png
    r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $img
  done
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-vplg4-$rep $B atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
done; done
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 150 $E/lll_tests --gtest_filter='InterleavedVpls.*:Gi.*:ComputeGlass.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi" $OUT/tests.log | head -8
cd $OUT && tar cJf r.tar.xz r tests.log && tar cf img.tar img && rm -rf r img tests.log; ls -la; true
