# run5: the GPU image suite with validation on the landed tree (every test that draws on the
# device; the CPU-only ones are left out as before), and the default scene and ThreeL's 16 lights at
# 1080p from the H200, to look at.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/img
W="--width 1920 --height 1080"
.gpu/bin/lll render atrium $W --out $OUT/img/atrium.png > $OUT/img/atrium.log 2>&1
.gpu/bin/lll render threel16 --technique lll $W --out $OUT/img/t16.png > $OUT/img/t16.log 2>&1
left=$((570 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout $left $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && xz -1 tests.log images.csv 2>/dev/null; tar cf img.tar img && rm -rf img; ls -la; true
