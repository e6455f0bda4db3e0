# run4: 9c47462 (new: vpl-filter from shared memory, the bitmap from 65 keys) against 9cfb2ef (old)
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  for k in 3 4; do
    img=/tmp/a.png; [ $rep = 1 ] && img=$OUT/img/$v-vpl$k.png
    r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $img
  done
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-vplg4-$rep $B atrium --gi vpl --vpl-interleave 4 --technique lll $W --frames 15 --out /tmp/a.png
  r $v-t16-$rep $B threel16 --technique lll $W --frames 150 --out /tmp/a.png
done; done
r new-vpl1-1 $N atrium --gi vpl-only --vpl-interleave 1 --technique lll $W --frames 3 --out $OUT/img/new-vpl1.png
echo renders done $SECONDS
timeout 120 $N bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/smoke > $OUT/smoke.log 2>&1; echo smoke rc=$? $SECONDS
left=$((560 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='InterleavedVpls.*:Gi.*:ComputeGlass.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*Vpl*:LllImages.*:Analytic*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r smoke smoke.log tests.log && tar cf img.tar img && rm -rf r img smoke smoke.log tests.log; ls -la; true
