# run1: smoke bench new (bitmap + opaque-group stop) vs old (9cfb2ef), particle GPU tests
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 120 $E/lll_tests --gtest_filter='ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|image" $OUT/tests.log | head -30
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  timeout 220 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz new old new.log old.log tests.log && rm -rf new old; ls -la; true
