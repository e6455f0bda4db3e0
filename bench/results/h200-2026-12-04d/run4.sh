# run4: the tree as it lands (final: ef6be62, the light records in shared memory reverted) against
# 0a2c859 (base): the GPU image suite with validation; settled smoke at 1080p, 65,536 and a million,
# and sparks and dust (65,536, atlas- and vertex-lit) with `lll render --stats`, two runs, images of
# the first; the light records in shared memory read through one function (shl2) against final:
# the threel bench (lll), and both shaders' registers (LLL_SHADER_STATS) on ThreeL's 16 lights.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 300 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in final) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361"
for rep in 1 2; do for v in base final; do
  I() { [ $rep = 1 ] && [ $1 != sparks-vertex ] && [ $1 != dust-vertex ] && echo $OUT/img/$v-$1.png || echo /tmp/a.png; }
  r $v-k65-$rep $(bin $v) $S --particles smoke --particle-lighting vertex --particle-count 65536 --out $(I k65)
  r $v-m1-$rep $(bin $v) $S --particles smoke --particle-lighting vertex --particle-count 1000000 --out $(I m1)
  for p in sparks dust; do for l in atlas vertex; do
    r $v-$p-$l-$rep $(bin $v) $S --particles $p --particle-lighting $l --particle-count 65536 --out $(I $p-$l)
  done; done
done; done
echo renders $SECONDS
for v in final shl2; do
  LLL_SHADER_STATS=1 timeout 60 $(bin $v) render threel16 --technique lll $W --out /tmp/a.png > $OUT/stats-$v.log 2>&1
  timeout 100 $(bin $v) bench --suite threel --technique lll --out $OUT/bench-$v > $OUT/bench-$v.log 2>&1; echo bench $v rc=$? $SECONDS
done
cd $OUT && xz -T4 tests.log && tar cJf r.tar.xz r bench-* *.log tests.log.xz && tar cf img-base.tar img/base-* && tar cf img-final.tar img/final-* && rm -rf r bench-* *.log img tests.log.xz; ls -la; true
