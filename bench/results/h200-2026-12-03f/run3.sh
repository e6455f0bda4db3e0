# run3: the puffs' two noise octaves baked into one texture, one read a pixel (new) against
# abfc459 (old, two reads); the smoke bench at 65,536 and a million, the GPU particle tests, then
# the rest of the GPU image suite in the time left
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 120 $E/lll_tests --gtest_filter='PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|image" $OUT/tests.log | head -30
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  local img=/tmp/a.png; case $n in *smoke-vertex-kf-1) img=$OUT/img/$n.png;; esac
  timeout 60 $bin render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 "$@" --stats $OUT/r/$n.json -o $img >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
for rep in 1 2 3; do
  for v in new old; do
    B=$N; [ $v = old ] && B=$O
    r $v-smoke-vertex-kf-$rep $B --particles smoke --particle-lighting vertex --particle-count 65536
    r $v-smoke-vertex-kh-$rep $B --particles smoke --particle-lighting vertex --particle-count 65536 --particle-resolution half
    r $v-smoke-vertex-mh-$rep $B --particles smoke --particle-lighting vertex --particle-count 1000000 --particle-resolution half
    r $v-smoke-vertex-mq-$rep $B --particles smoke --particle-lighting vertex --particle-count 1000000 --particle-resolution quarter
  done
  echo rep $rep $SECONDS
done
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  timeout 150 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
left=$((575 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='-PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests-rest.log 2>&1; echo rest rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|tests ran" $OUT/tests-rest.log | head; grep -c "^\[       OK" $OUT/tests-rest.log
cd $OUT && tar cJf r.tar.xz r new old new.log old.log tests.log tests-rest.log && tar cf img.tar img && rm -rf r img new old new.log old.log tests.log; ls -la; true
