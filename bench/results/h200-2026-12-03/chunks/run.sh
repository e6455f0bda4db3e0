set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
B=.gpu/bin; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 60 $bin render "$@" --out /tmp/a.png --stats $OUT/r/$n.json >/dev/null 2>&1 || echo fail $n; }
for rep in 1 2; do
for bin in $E/lll_old $B/lll; do
  b=$(basename $bin)
  r $b-t16-$rep $bin threel16 --technique lll --width 1920 --height 1080 --frames 200
  r $b-t16k-$rep $bin threel16 --technique lll --width 3840 --height 2160 --frames 100
  r $b-t256-$rep $bin threel256 --technique lll --width 1920 --height 1080 --frames 100
  r $b-a1024-$rep $bin atrium --lights 1024 --technique lll --width 1920 --height 1080 --frames 150
  r $b-f16-$rep $bin threel16 --technique forward --width 1920 --height 1080 --frames 150
  r $b-f256-$rep $bin threel256 --technique forward --width 1920 --height 1080 --frames 100
  r $b-tiled16-$rep $bin threel16 --technique tiled --width 1920 --height 1080 --frames 150
  r $b-tiled1024-$rep $bin atrium --lights 1024 --technique tiled --width 1920 --height 1080 --frames 150
  r $b-vpl16-$rep $bin atrium --gi vpl-only --tile 16 --technique lll --width 1920 --height 1080 --frames 40
done; done
echo renders done $SECONDS
$B/lll render threel16 --technique lll --width 1920 --height 1080 --out $OUT/img/t16.png >/dev/null 2>&1
$B/lll render threel256 --technique lll --width 1920 --height 1080 --out $OUT/img/t256.png >/dev/null 2>&1
$B/lll render atrium --lights 1024 --technique lll --width 1920 --height 1080 --out $OUT/img/a1024.png >/dev/null 2>&1
$B/lll render atrium --gi vpl-only --tile 16 --technique lll --width 1920 --height 1080 --out $OUT/img/vpl16.png >/dev/null 2>&1
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout 330 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -4 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20
cd $OUT && tar cf r.tar r img && rm -rf r img && xz -1 images.csv
