# run5: particles-composite evaluating two staged particles before blending them (new, working tree on
# 0fdb410) against 0fdb410 (old): the particle tests of new, a settled smoke frame of each (vertex),
# the smoke bench of each, the composite's driver statistics
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_h; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.txt 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.txt | head -10
for l in vertex atlas; do
LLL_SHADER_STATS=1 timeout 60 $N render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 2 --particles smoke --particle-lighting $l --particle-count 65536 -o /tmp/a.png 2>&1 | grep "shader stats" | grep -i "particles_tiles" >> $OUT/shader-stats.txt
done
mkdir -p $OUT/img
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  timeout 90 $B render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 --particles smoke --particle-lighting vertex --particle-count 65536 -o $OUT/img/$v-smoke.png > /dev/null 2>$OUT/img/$v.err || echo fail $v
done
echo renders $SECONDS
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  timeout 170 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz new old new.log old.log && tar cf img.tar img && rm -rf img new old new.log old.log; ls -la; true
