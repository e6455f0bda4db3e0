set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; E=.gpu/extra
mkdir -p $OUT/r
W="--width 1920 --height 1080"
timeout 30 $N render threel16 --technique lll $W --frames 150 --stats $OUT/r/t16.json --out /tmp/a.png > /dev/null 2>&1 || echo fail t16
timeout 30 $N render threel16 --technique lll --width 3840 --height 2160 --frames 60 --stats $OUT/r/t16k.json --out /tmp/a.png > /dev/null 2>&1 || echo fail t16k
echo renders $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 225 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r tests.log && rm -rf r tests.log; ls -la; true
