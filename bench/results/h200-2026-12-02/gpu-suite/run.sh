source .gpu/setup.sh
set +e
SECONDS=0
cd /work/main
export LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv
mkdir -p $OUT/fail; export LLL_TEST_IMAGE_DIR=$OUT/fail
timeout 330 build/tests/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1
echo "tests rc=$? in ${SECONDS}s"
grep -E '^\[  (PASSED|FAILED) ' $OUT/tests.log | head -30; grep -c '^\[       OK' $OUT/tests.log
cd $OUT && tar czf fail.tar.gz fail && rm -rf fail
