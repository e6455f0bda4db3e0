# run6: the particle tests of 73b0214 (the landed tree); where particles-composite's time goes, by
# removing parts of it (the images are wrong, the times are not the renderer's): d1 blends the
# cell's particles in the order binning left them (no shared-memory sort or bitmap), d2 stages the
# particles but evaluates none (and so no pixel finishes early); the smoke bench of each and of
# 73b0214 (old)
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.txt 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.txt | head -10
for v in old d1 d2; do
  B=$E/lll_h2; [ $v = d1 ] && B=$E/lll_d1; [ $v = d2 ] && B=$E/lll_d2
  timeout 170 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz old d1 d2 old.log d1.log d2.log && rm -rf old d1 d2 *.log; ls -la; true
