# run8: a cell's keys put in order by rank (each invocation counts the keys below its own; three
# barriers) instead of a bitonic sort in shared memory: r64 sorts cells of up to 64 keys so (the
# bitmap beyond, as before), r256 up to 256; old = 73b0214. The particle tests of r256, a settled
# smoke frame of each (vertex), the smoke bench of each
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/extra/lll_r256 build/lll
E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.txt 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.txt | head -10
mkdir -p $OUT/img
for v in old r64 r256; do
  B=$E/lll_h2; [ $v = r64 ] && B=$E/lll_r64; [ $v = r256 ] && B=$E/lll_r256
  timeout 90 $B render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 --particles smoke --particle-lighting vertex --particle-count 65536 -o $OUT/img/$v-smoke.png > /dev/null 2>$OUT/img/$v.err || echo fail $v
done
echo renders $SECONDS
for v in old r64 r256; do
  B=$E/lll_h2; [ $v = r64 ] && B=$E/lll_r64; [ $v = r256 ] && B=$E/lll_r256
  timeout 170 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz old r64 r256 *.log && tar cf img.tar img && rm -rf img old r64 r256 *.log; ls -la; true
