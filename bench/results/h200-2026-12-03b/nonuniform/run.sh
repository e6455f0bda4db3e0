set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
B=.gpu/bin; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --out /tmp/a.png --stats $OUT/r/$n.json >/dev/null 2>&1 || echo fail $n; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for bin in $E/lll_old $B/lll; do
  b=$(basename $bin)
  r $b-t16-$rep $bin threel16 --technique lll $W --frames 200
  r $b-t16k-$rep $bin threel16 --technique lll --width 3840 --height 2160 --frames 100
  r $b-t256-$rep $bin threel256 --technique lll $W --frames 100
  r $b-a1024-$rep $bin atrium --lights 1024 --technique lll $W --frames 150
  r $b-atrium-$rep $bin atrium --technique lll $W --frames 150
  r $b-f16-$rep $bin threel16 --technique forward $W --frames 200
  r $b-tiled16-$rep $bin threel16 --technique tiled $W --frames 200
  r $b-vpl16k3-$rep $bin atrium --gi vpl-only --tile 16 --vpl-interleave 3 --technique lll $W --frames 40
done
  b=lll_T16
  r $b-t16-$rep $B/lll threel16 --technique lll $W --frames 200 --tile 16
  r $b-t16k-$rep $B/lll threel16 --technique lll --width 3840 --height 2160 --frames 100 --tile 16
  r $b-t256-$rep $B/lll threel256 --technique lll $W --frames 100 --tile 16
  r $b-a1024-$rep $B/lll atrium --lights 1024 --technique lll $W --frames 150 --tile 16
  r $b-atrium-$rep $B/lll atrium --technique lll $W --frames 150 --tile 16
  r lll_S1-t16-$rep $B/lll threel16 --technique lll $W --frames 200 --lll-slices 1
done
echo renders done $SECONDS
$B/lll render threel16 --technique lll $W --out $OUT/img/t16.png >/dev/null 2>&1
$E/lll_old render threel16 --technique lll $W --out $OUT/img/t16_old.png >/dev/null 2>&1
$B/lll render atrium --lights 1024 --technique lll $W --out $OUT/img/a1024.png >/dev/null 2>&1
$E/lll_old render atrium --lights 1024 --technique lll $W --out $OUT/img/a1024_old.png >/dev/null 2>&1
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout 330 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20
cd $OUT && tar cf r.tar r img && rm -rf r img && xz -1 images.csv
