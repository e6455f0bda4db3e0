set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_old; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 60 $bin render "$@" --out /tmp/a.png --stats $OUT/r/$n.json >/dev/null 2>&1 || echo fail $n; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for v in old new; do
  B=$N; [ $v = old ] && B=$O
  r $v-t16-$rep $B threel16 --technique lll $W --frames 200
  r $v-t16k-$rep $B threel16 --technique lll --width 3840 --height 2160 --frames 80
  r $v-t256-$rep $B threel256 --technique lll $W --frames 60
  r $v-a1024-$rep $B atrium --lights 1024 --technique lll $W --frames 150
  r $v-atrium-$rep $B atrium --technique lll $W --frames 150
  r $v-f16-$rep $B threel16 --technique forward $W --frames 200
  r $v-tiled16-$rep $B threel16 --technique tiled $W --frames 200
  r $v-vpl3-$rep $B atrium --gi vpl-only --vpl-interleave 3 --technique lll $W --frames 30
done
r new-S1t16-$rep $N threel16 --technique lll $W --frames 200 --lll-slices 1
done
for sp in 32; do
  r new-sp$sp-a1024-1 $N atrium --lights 1024 --technique lll $W --frames 150 --lll-fill-splits $sp
  r new-sp$sp-t256-1 $N threel256 --technique lll $W --frames 60 --lll-fill-splits $sp
done
echo renders done $SECONDS
$N render threel16 --technique lll $W --out $OUT/img/t16.png >/dev/null 2>&1
$O render threel16 --technique lll $W --out $OUT/img/t16_old.png >/dev/null 2>&1
$N render atrium --lights 1024 --technique lll $W --out $OUT/img/a1024.png >/dev/null 2>&1
$O render atrium --lights 1024 --technique lll $W --out $OUT/img/a1024_old.png >/dev/null 2>&1
timeout 150 $N bench --suite threel --suite tiles --technique lll --technique forward --out $OUT/bench > $OUT/bench.log 2>&1 || echo bench failed
echo bench done $SECONDS
left=$((575 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout $left $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20
cd $OUT && tar cf r.tar r img bench bench.log && rm -rf r img bench bench.log; xz -1 images.csv 2>/dev/null; true
