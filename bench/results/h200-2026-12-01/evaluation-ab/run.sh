source .gpu/setup.sh
set +e
SECONDS=0
cd /work/main
cp $g/extra/lll_old build/lll_old
export LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv
mkdir -p $OUT/fail $OUT/r; export LLL_TEST_IMAGE_DIR=$OUT/fail
timeout 330 build/tests/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1
echo "tests rc=$? in ${SECONDS}s"
grep -E '^\[  (PASSED|FAILED) ' $OUT/tests.log | head -30; grep -c '^\[       OK' $OUT/tests.log
unset LLL_TEST_VALIDATION
R="--device gpu --width 1920 --height 1080 --frames 30"
run() { n=$1; shift; for b in lll_old lll; do timeout 40 build/$b render "$@" $R --out $OUT/r/$n-$b.png > $OUT/r/$n-$b.log 2>&1; done; }
run t16 threel16 --technique lll
run t256 threel256 --technique lll
run a1024 atrium --technique lll --lights 1024
run t16f threel16 --technique forward
G="atrium --technique lll --tile 16 --gi vpl-only"
run h5k1 $G --vpl-interleave 1
run h5k2 $G --vpl-interleave 2
run h5k3 $G --vpl-interleave 3
run h64k2 $G --vpl-count 65536 --photons 196608 --vpl-interleave 2
run h64k3 $G --vpl-count 65536 --photons 196608 --vpl-interleave 3
echo "renders done in ${SECONDS}s"
cd $OUT/r && for f in *-lll.log; do n=${f%-lll.log}; for k in frame shade-opaque glass lll-fill-compute vpl-filter; do a=$(grep " $k " $n-lll_old.log | awk '{print $(NF-1)}'); b=$(grep " $k " $n-lll.log | awk '{print $(NF-1)}'); [ -n "$a$b" ] && echo "$n $k old=$a new=$b"; done; done
cd $OUT && tar czf r.tar.gz r fail && rm -rf r fail
