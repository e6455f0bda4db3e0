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
  [ $rep = 1 ] || continue
  r $v-t16k-$rep $B threel16 --technique lll --width 3840 --height 2160 --frames 60
  r $v-a1024-$rep $B atrium --lights 1024 --technique lll $W --frames 100
  r $v-atrium-$rep $B atrium --technique lll $W --frames 100
  r $v-f16-$rep $B threel16 --technique forward $W --frames 150
  r $v-vpl3-$rep $B atrium --gi vpl-only --vpl-interleave 3 --technique lll $W --frames 15
done; done
echo renders done $SECONDS
$N render threel16 --technique lll $W --out $OUT/img/t16.png >/dev/null 2>&1
$N render atrium --lights 1024 --technique lll $W --out $OUT/img/a1024.png >/dev/null 2>&1
timeout 60 $N bench --suite threel --suite tiles --technique lll --out $OUT/bench > $OUT/bench.log 2>&1 || echo bench failed
echo bench done $SECONDS
left=$((335 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout $left $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cf r.tar r img bench bench.log && rm -rf r img bench bench.log; xz -1 images.csv 2>/dev/null; true
