# run3: VPL lobes split + edge ring (new) vs 9cfb2ef (old); 69b9518's million-slot stall re-run; GPU tests
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; S=.gpu/extra/lll_69b; E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
W="--width 1920 --height 1080"
# 69b9518: the million-slot renders that stalled on 2026-11-22 (raster particles, vertex-lit)
for f in 2 361; do
  s=$SECONDS; timeout 60 $S render atrium --lights 256 --particles smoke --particle-count 1000000 --particle-lighting vertex --technique lll $W --frames $f --stats $OUT/r/stall69-$f.json -o /tmp/s.png > $OUT/r/stall69-$f.log 2>&1; echo "69b9518 frames $f rc=$? $((SECONDS - s)) s"
done
for rep in 1 2; do
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  for k in 3 4; do r $v-vpl$k-$rep $B atrium --gi vpl-only --vpl-interleave $k --technique lll $W --frames 15 --out $OUT/img/$v-vpl$k.png; [ $rep = 1 ] || rm -f $OUT/img/$v-vpl$k.png; done
  r $v-vpl65k4-$rep $B atrium --gi vpl-only --vpl-count 65536 --photons 196608 --vpl-interleave 4 --technique lll $W --frames 10 --out /tmp/a.png
  r $v-t16-$rep $B threel16 --technique lll $W --frames 150 --out /tmp/a.png
  [ $rep = 1 ] && [ $v = new ] && r new-vpl1-1 $B atrium --gi vpl-only --vpl-interleave 1 --technique lll $W --frames 3 --out $OUT/img/new-vpl1.png
done; done
# the bitmap from 65 keys a cell (lll_bm64) against from 1,025 (new)
P="atrium --lights 256 --particles smoke --particle-render compute --technique lll $W --frames 361 --particle-lighting vertex"
for rep in 1 2; do for v in new bm64; do
  B=$N; [ $v = bm64 ] && B=$E/lll_bm64
  r $v-kf-$rep $B $P --particle-count 65536 --out /tmp/a.png
  r $v-kq-$rep $B $P --particle-count 65536 --particle-resolution quarter --out /tmp/a.png
  r $v-mq-$rep $B $P --particle-count 1000000 --particle-resolution quarter --out /tmp/a.png
done; done
echo renders done $SECONDS
left=$((575 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='InterleavedVpls.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*' > $OUT/tests-first.log 2>&1; echo first tests rc=$? $SECONDS
left=$((575 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout $left $E/lll_tests --gtest_filter='-InterleavedVpls.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|\[ gi" $OUT/tests-first.log $OUT/tests.log | head -30; grep -c "^\[       OK" $OUT/tests-first.log $OUT/tests.log
cd $OUT && xz -1 images.csv 2>/dev/null; tar cJf r.tar.xz r tests.log tests-first.log && tar cf img.tar img && rm -rf r img tests.log tests-first.log; ls -la; true
