# run2: particles-bin's prefix sum in blocks and atlas lighting an invocation per texel (new)
# against 5ac0a2e (old): the smoke bench at 65,536 and a million, sparks and dust, the GPU tests
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 120 $E/lll_tests --gtest_filter='ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|image" $OUT/tests.log | head -30
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  local img=/tmp/a.png; case $n in *dust-atlas-kf-1|*sparks-atlas-kf-1) img=$OUT/img/$n.png;; esac
  timeout 60 $bin render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 "$@" --stats $OUT/r/$n.json -o $img >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
for rep in 1 2; do
  for v in new old; do
    B=$N; [ $v = old ] && B=$O
    for p in sparks dust; do for l in atlas vertex; do
      r $v-$p-$l-kf-$rep $B --particles $p --particle-lighting $l --particle-count 65536
    done; done
    r $v-smoke-atlas-kf-$rep $B --particles smoke --particle-lighting atlas --particle-count 65536
    r $v-smoke-vertex-kf-$rep $B --particles smoke --particle-lighting vertex --particle-count 65536
    r $v-smoke-vertex-mh-$rep $B --particles smoke --particle-lighting vertex --particle-count 1000000 --particle-resolution half
  done
  echo rep $rep $SECONDS
done
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  timeout 150 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz r new old new.log old.log tests.log && tar cf img.tar img && rm -rf r img new old new.log old.log tests.log; ls -la; true
