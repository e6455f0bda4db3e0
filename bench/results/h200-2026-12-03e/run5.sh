# run5: vpl-filter with the lobes and the ring (ring = the tree at HEAD), without the ring (noring), 9cfb2ef (old)
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll_ring build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for v in ring noring old; do
  B=.gpu/bin/lll_ring; [ $v = old ] && B=$E/lll_head; [ $v = noring ] && B=$E/lll_noring
  img=/tmp/a.png; [ $rep = 1 ] && [ $v != old ] && img=$OUT/img/$v-vpl4.png
  r $v-vpl4-$rep $B atrium --gi vpl-only --vpl-interleave 4 --technique lll $W --frames 15 --out $img
  r $v-vpl3-$rep $B atrium --gi vpl-only --vpl-interleave 3 --technique lll $W --frames 15 --out /tmp/a.png
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-vplg4-$rep $B atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
done; done
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 150 $E/lll_tests --gtest_filter='InterleavedVpls.*:Gi.*:ComputeGlass.Lll*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi" $OUT/tests.log | head -12
cd $OUT && tar cJf r.tar.xz r tests.log && tar cf img.tar img && rm -rf r img tests.log; ls -la; true
