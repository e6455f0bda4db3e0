# run3: the composite's staged particles packed (a 16-byte disc every pixel reads, a 16-byte look of
# half floats a covered pixel reads; pack) against the landed tree's (noise, b035d90's shaders):
# the smoke bench of each, twice, interleaved; settled smoke frames; registers; the particle tests on
# pack's tests binary.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in pack) echo .gpu/bin/lll;; noise) echo $E/lll_noise;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361 --particles smoke"
for v in noise pack; do
  LLL_SHADER_STATS=1 timeout 60 $(bin $v) render $S --particle-lighting vertex --particle-count 65536 --out /tmp/a.png 2>&1 | grep particles_tiles > $OUT/r/$v-shader-stats.txt
  r $v-smoke64k $(bin $v) $S --particle-lighting vertex --particle-count 65536 --out $OUT/img/$v-smoke64k.png
  r $v-smoke1m-half $(bin $v) $S --particle-lighting vertex --particle-count 1000000 --particle-resolution half --out $OUT/img/$v-smoke1m-half.png
done
echo renders $SECONDS
for rep in 1 2; do for v in noise pack; do
  timeout 150 $(bin $v) bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-$v-$rep > $OUT/bench-$v-$rep.log 2>&1; echo bench $v rc=$? $SECONDS
done; done
left=$((570 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:SoftParticles.*:SmokeInOtherTechniques.*:*SmokeMatchesForward*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-* *.log && tar cf img.tar img && rm -rf r img bench-* *.log; ls -la; true
