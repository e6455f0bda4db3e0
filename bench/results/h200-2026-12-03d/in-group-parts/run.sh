# run1.sh (binaries: lll = the glass pass sharing a layer's parts among its group's invocations, not
# kept; lll_head = 475110b; lll_nometal = the same with evaluatesEveryClass() false, a probe)
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; M=.gpu/extra/lll_nometal; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for v in old new; do
  B=$N; [ $v = old ] && B=$O
  for k in 1 2 3 4; do r $v-vpl$k $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $OUT/img/$v-vpl$k.png; [ $k = 3 ] || rm -f $OUT/img/$v-vpl$k.png; done
  for k in 2 3; do r $v-vpl65k$k $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave $k --technique lll $W --frames 10 --out /tmp/a.png; done
  r $v-tiled-vpl1 $B atrium --gi vpl-only --technique tiled $W --frames 10 --out /tmp/a.png
  r $v-t16 $B threel16 --technique lll $W --frames 150 --out /tmp/a.png
  r $v-a1024 $B atrium --lights 1024 --technique lll $W --frames 100 --out /tmp/a.png
  r $v-a131k $B atrium --lights 131072 --technique lll --tile 16 --lll-slices 16 $W --frames 20 --out /tmp/a.png
done
for k in 3 4; do r nometal-vpl$k $M atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out /tmp/a.png; done
r nometal-vpl65k3 $M atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 3 --technique lll $W --frames 10 --out /tmp/a.png
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 150 $E/lll_tests --gtest_filter='ComputeGlass.*:Gi.Every*:InterleavedVpls.*:GlassAndParticles.*:DeferredMatchesForward.*:Glass.*:DeferredTranslucent.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head
left=$((520 - SECONDS))
timeout $left $N bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 9 --warmup 3 --out $OUT/smoke > $OUT/smoke.log 2>&1 || echo smoke rc $?
echo smoke done $SECONDS
cd $OUT && rm -f smoke/*.png smoke/*.svg; tar cJf r.tar.xz r smoke smoke.log tests.log && tar cf img.tar img && rm -rf r img smoke smoke.log tests.log; ls -la; true
