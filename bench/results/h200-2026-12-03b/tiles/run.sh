set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
B=.gpu/bin/lll; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1; shift
  timeout 90 $B render "$@" --out /tmp/a.png --stats $OUT/r/$n.json >/dev/null 2>&1 || echo fail $n; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for t in 8 16; do
  b=T$t; T="--tile $t"
  r $b-t16-$rep threel16 --technique lll $W --frames 200 $T
  r $b-t16k-$rep threel16 --technique lll --width 3840 --height 2160 --frames 100 $T
  r $b-t256-$rep threel256 --technique lll $W --frames 100 $T
  r $b-a1024-$rep atrium --lights 1024 --technique lll $W --frames 150 $T
  r $b-atrium-$rep atrium --technique lll $W --frames 150 $T
  r $b-d4k-$rep atrium --lights 4096 --light-range-scale 0.63 --technique lll $W --frames 100 $T
  r $b-f16-$rep threel16 --technique forward $W --frames 200 $T
  r $b-tiled16-$rep threel16 --technique tiled $W --frames 200 $T
  r $b-tileda-$rep atrium --lights 1024 --technique tiled $W --frames 150 $T
  r $b-clusta-$rep atrium --lights 1024 --technique clustered $W --frames 150 $T
  r $b-S1t16-$rep threel16 --technique lll $W --frames 200 $T --lll-slices 1
  export LLL_GLASS_EARLY=1
  r $b-Gt16-$rep threel16 --technique lll $W --frames 200 $T
  r $b-Ga1024-$rep atrium --lights 1024 --technique lll $W --frames 150 $T
  r $b-Gatrium-$rep atrium --technique lll $W --frames 150 $T
  r $b-Gf16-$rep threel16 --technique forward $W --frames 200 $T
  unset LLL_GLASS_EARLY
done
  if [ $rep = 1 ]; then for sp in 4 8 16; do for t in 8 16; do b=T$t-sp$sp; T="--tile $t --lll-fill-splits $sp"
    [ $t = 16 ] && r $b-t16-$rep threel16 --technique lll $W --frames 200 $T
    r $b-t256-$rep threel256 --technique lll $W --frames 100 $T
    r $b-a1024-$rep atrium --lights 1024 --technique lll $W --frames 150 $T
    [ $t = 16 ] && r $b-atrium-$rep atrium --technique lll $W --frames 150 $T
    [ $t = 16 ] && r $b-d4k-$rep atrium --lights 4096 --light-range-scale 0.63 --technique lll $W --frames 100 $T
  done; done; fi
  r T16-vpl16k3-$rep atrium --gi vpl-only --tile 16 --vpl-interleave 3 --technique lll $W --frames 40
done
echo renders done $SECONDS
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout 290 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20
cd $OUT && tar cf r.tar r && rm -rf r img && xz -1 images.csv
