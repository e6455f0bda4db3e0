# run4: the puff noise as one filtered read of the 64 x 64 lattice at a smoothstep-moved
# coordinate (new, working tree on 4871c32) against 4871c32 (old: the 256 x 256 baked texture):
# the particle tests of new, a settled smoke frame of each, the smoke bench of each
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_h; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.txt 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.txt | head -10
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
