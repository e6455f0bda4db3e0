# run2: the puffs' noise in one read (two octaves baked in the same 256x256 texture: lattice period
# 32, 8 texels a cell; noise) and the composite blending one layer at a time (all = noise + the
# single layer; both on top of the BRDF change of run1) against 14a21ee (old): the smoke bench of
# each (65,536 and a million slots), settled smoke frames of each, registers; the particle tests on
# all's tests binary; two more runs of run1's renders (old, brdf).
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in all) echo .gpu/bin/lll;; noise) echo $E/lll_noise;; brdf) echo $E/lll_brdf;; old) echo $E/lll_old;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361 --particles smoke"
LLL_SHADER_STATS=1 timeout 60 .gpu/bin/lll render $S --particle-lighting vertex --particle-count 65536 --out /tmp/a.png > $OUT/r/all-shader-stats.txt 2>&1
for v in old noise all; do
  B=$(bin $v)
  r $v-smoke64k $B $S --particle-lighting vertex --particle-count 65536 --out $OUT/img/$v-smoke64k.png
  r $v-smoke64k-atlas $B $S --particle-lighting atlas --particle-count 65536 --out $OUT/img/$v-smoke64k-atlas.png
  r $v-smoke1m-half $B $S --particle-lighting vertex --particle-count 1000000 --particle-resolution half --out $OUT/img/$v-smoke1m-half.png
done
echo renders $SECONDS
for v in old noise all; do
  timeout 150 $(bin $v) bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-$v > $OUT/bench-$v.log 2>&1; echo bench $v rc=$? $SECONDS
done
for rep in 2 3; do for v in old brdf; do
  B=$(bin $v)
  r $v-t16-$rep $B threel16 --technique lll $W --frames 200 --out /tmp/a.png
  r $v-t256-$rep $B threel256 --technique lll $W --frames 60 --out /tmp/a.png
  r $v-f256-$rep $B threel256 --technique forward $W --frames 40 --out /tmp/a.png
  r $v-a1024-$rep $B atrium --lights 1024 --technique lll $W --frames 100 --out /tmp/a.png
done; done
echo renders2 $SECONDS
left=$((570 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:SoftParticles.*:SmokeInOtherTechniques.*:*SmokeMatchesForward*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-old bench-noise bench-all *.log && for v in old noise all; do tar cf img-$v.tar img/$v-*; done && rm -rf r img bench-* *.log; ls -la; true
