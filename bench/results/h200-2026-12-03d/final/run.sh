# run3.sh (lll = b35a0c7's tree: glass-light and vpl-classes; lll_head = 475110b; lll_tests = the
# test binary of b35a0c7's tree: the GPU image suite with validation, tests.txt)
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
for rep in 1 2; do
for v in old new; do
  B=$N; [ $v = old ] && B=$O
  for k in 2 3 4; do r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $OUT/img/$v-vpl$k.png; [ $k = 2 ] && rm -f $OUT/img/$v-vpl$k.png; [ $rep = 1 ] || rm -f $OUT/img/$v-vpl$k.png; done
  for k in 2 3 4; do r $v-vpl65k$k-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave $k --technique lll $W --frames 10 --out /tmp/a.png; done
  [ $rep = 1 ] || continue
  for k in 3 4; do r $v-vplg$k-$rep $B atrium --gi vpl --vpl-interleave $k --technique lll $W --frames 15 --out /tmp/a.png; done
  r $v-t16-$rep $B threel16 --technique lll $W --frames 150 --out /tmp/a.png
  r $v-a1024-$rep $B atrium --lights 1024 --technique lll $W --frames 100 --out /tmp/a.png
done; done
echo renders done $SECONDS
left=$((470 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout $left $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && xz -1 images.csv 2>/dev/null; tar cJf r.tar.xz r tests.log && tar cf img.tar img && rm -rf r img tests.log; ls -la; true
