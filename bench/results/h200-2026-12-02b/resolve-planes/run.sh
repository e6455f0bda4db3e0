set -u
source .gpu/setup.sh
ln -sfn "$(pwd)" /tmp/wt
mkdir -p build/tests && cp .gpu/bin/lll build/lll
B=.gpu/bin; E=.gpu/extra
mkdir -p $OUT/r
for rep in 1 2; do
for bin in $E/lll_old $B/lll; do
  n=$(basename $bin)
  $bin render threel16 --technique lll --width 1920 --height 1080 --frames 200 --out /tmp/a.png --stats $OUT/r/$n-t16-$rep.json >/dev/null 2>&1 || echo fail $n t16
  $bin render threel16 --technique lll --width 3840 --height 2160 --frames 120 --out /tmp/a.png --stats $OUT/r/$n-t16k-$rep.json >/dev/null 2>&1 || echo fail $n t16k
  $bin render threel256 --technique lll --width 1920 --height 1080 --frames 120 --out /tmp/a.png --stats $OUT/r/$n-t256-$rep.json >/dev/null 2>&1 || echo fail $n t256
  $bin render atrium --lights 1024 --technique lll --width 1920 --height 1080 --frames 150 --out /tmp/a.png --stats $OUT/r/$n-a1024-$rep.json >/dev/null 2>&1 || echo fail $n a1024
  $bin render threel16 --technique lll --sun 0.3,-1,0.2,20 --shadows sun --width 1920 --height 1080 --frames 100 --out /tmp/a.png --stats $OUT/r/$n-sun-$rep.json >/dev/null 2>&1 || echo fail $n sun
done; done
echo renders done $SECONDS
$B/lll bench --suite threel --out $OUT/bench > $OUT/bench.log 2>&1 || echo bench failed
echo bench done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout 330 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -4 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20
cd $OUT && tar cf r.tar r bench && rm -rf r bench && xz -1 images.csv
