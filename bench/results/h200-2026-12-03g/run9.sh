# run9: the landed tree (0391eac, rank-ordered cells): the particle tests with validation, a settled
# smoke frame (vertex, 65,536, 1080p), the smoke bench
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.txt 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.txt | head -10
timeout 90 .gpu/bin/lll render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 --particles smoke --particle-lighting vertex --particle-count 65536 -o $OUT/smoke.png > /dev/null 2>&1 || echo render failed
timeout 170 .gpu/bin/lll bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/new > $OUT/new.log 2>&1; echo new rc=$? $SECONDS
cd $OUT && tar cJf r.tar.xz new new.log && rm -rf new new.log; ls -la; true
