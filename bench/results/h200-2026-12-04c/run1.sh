# run1: the per-light BRDF in fewer instructions (brdf: the half vector's dot products from l.v,
# the colour's arithmetic as scalar weights) against 14a21ee (old): ThreeL's 16 and 256 lights, forward
# on both, the atrium + 1,024 lights, the atrium's 5,144 VPLs at K = 4; two runs each, interleaved;
# images of each; `lll bench --suite threel` of each (the ALU probe); registers; the tests that
# compare shading with the references, on the working tree's binary (new: brdf + the puff noise in one
# read + the composite's single layer).
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img-old $OUT/img-brdf
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in brdf) echo $E/lll_brdf;; old) echo $E/lll_old;; esac; }
W="--width 1920 --height 1080"
for v in old brdf; do LLL_SHADER_STATS=1 timeout 60 $(bin $v) render threel256 --technique lll $W --frames 1 --out /tmp/a.png > $OUT/r/$v-shader-stats.txt 2>&1; done
for rep in 1 2; do
for v in old brdf; do
  B=$(bin $v); I=/tmp/a.png; [ $rep = 1 ] && I=$OUT/img-$v
  r $v-t16-$rep $B threel16 --technique lll $W --frames 200 --out $I/t16.png
  r $v-t256-$rep $B threel256 --technique lll $W --frames 60 --out $I/t256.png
  r $v-f16-$rep $B threel16 --technique forward $W --frames 150 --out $I/f16.png
  r $v-f256-$rep $B threel256 --technique forward $W --frames 40 --out $I/f256.png
  r $v-a1024-$rep $B atrium --lights 1024 --technique lll $W --frames 100 --out $I/a1024.png
  r $v-vpl4-$rep $B atrium --gi vpl-only --vpl-interleave 4 --technique lll $W --frames 15 --out $I/vpl4.png
done; done
echo renders done $SECONDS
for v in old brdf; do
  timeout 100 $(bin $v) bench --suite threel --technique lll --technique forward --out $OUT/bench-$v > $OUT/bench-$v.log 2>&1; echo bench $v rc=$? $SECONDS
done
left=$((560 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='ShadingPaths/Analytic.*:AnalyticLights.*:EveryTechniqueEveryScene*:Atrium*:ThreeL*:InterleavedVpls.*:Gi.*:GiReference.*:ComputeGlass.*:Glass.*:DeferredMatchesForward*:PrepassMatchesForward*:Sun*:LocalShadows*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-old bench-brdf *.log && tar cf img-old.tar img-old && tar cf img-brdf.tar img-brdf && rm -rf r img-old img-brdf bench-old bench-brdf *.log; ls -la; true
