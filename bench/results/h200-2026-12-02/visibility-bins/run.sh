source .gpu/setup.sh
set +e
SECONDS=0
cd /work/main
cp $g/extra/lll_old build/lll_old
export LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv
mkdir -p $OUT/fail $OUT/r; export LLL_TEST_IMAGE_DIR=$OUT/fail
timeout 300 build/tests/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1
echo "tests rc=$? in ${SECONDS}s"
grep -E '^\[  (PASSED|FAILED) ' $OUT/tests.log | head -30; grep -c '^\[       OK' $OUT/tests.log
unset LLL_TEST_VALIDATION
R="--device gpu --frames 100"
P=' (visibility|visibility-bins|visibility-resolve|shade-opaque|frame) '
run() { n=$1; shift; for b in lll_old lll; do timeout 40 build/$b render "$@" $R --out $OUT/r/$n-$b.png > $OUT/r/$n-$b.log 2>&1; grep -E "$P" $OUT/r/$n-$b.log | sed "s/^/$n $b /"; done; }
run t16 threel16 --technique lll --width 1920 --height 1080
run t16-4k threel16 --technique lll --width 3840 --height 2160
run t256 threel256 --technique lll --width 1920 --height 1080
run a1024 atrium --technique lll --lights 1024 --width 1920 --height 1080
run f16 threel16 --technique forward --width 1920 --height 1080
run plane plane --technique lll --width 1920 --height 1080
echo "renders done in ${SECONDS}s"
cp $OUT/r/t16-lll.png $OUT/gpu-t16.png
cd $OUT && tar czf rlogs.tar.gz r/*.log fail && rm -rf r fail
cd /work/main
timeout $((560-SECONDS)) build/lll bench --device gpu --suite threel --technique lll --technique forward --frames 20 --warmup 5 --out $OUT/threel > $OUT/threel.log 2>&1
echo "threel rc=$? at ${SECONDS}s"
cd $OUT && tar czf threel.tar.gz threel threel.log && rm -rf threel threel.log
