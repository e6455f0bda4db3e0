# run1: particles-bin culls the slabs behind a tile's opaque ones and the groups share out the live
# slabs (new) against 5ac0a2e (old); groups swept; sparks and dust; the particle tests on the GPU
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 120 $E/lll_tests --gtest_filter='ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|image" $OUT/tests.log | head -30
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  local img=/tmp/a.png; [ ${n##*-} = 1 ] && img=$OUT/img/$n.png
  timeout 60 $bin render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 "$@" --stats $OUT/r/$n.json -o $img >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
S="--particles smoke --particle-lighting vertex"
for rep in 1 2; do
  for g in 1 2 4 8; do r new-kf$g-$rep $N $S --particle-count 65536 --particle-tile-groups $g; done
  for g in 1 4; do r nocull-kf$g-$rep $N $S --particle-count 65536 --particle-tile-groups $g --no-particle-cull; done
  r old-kf1-$rep $O $S --particle-count 65536 --particle-tile-groups 1
  for g in 4 8 16; do r new-kh$g-$rep $N $S --particle-count 65536 --particle-resolution half --particle-tile-groups $g; done
  r old-kh4-$rep $O $S --particle-count 65536 --particle-resolution half --particle-tile-groups 4
  for g in 1 4 16; do r new-mf$g-$rep $N $S --particle-count 1000000 --particle-tile-groups $g; done
  for g in 8 16 32; do r new-mh$g-$rep $N $S --particle-count 1000000 --particle-resolution half --particle-tile-groups $g; done
  r old-mh16-$rep $O $S --particle-count 1000000 --particle-resolution half --particle-tile-groups 16
  for g in 16 32; do r new-mq$g-$rep $N $S --particle-count 1000000 --particle-resolution quarter --particle-tile-groups $g; done
  r old-mq16-$rep $O $S --particle-count 1000000 --particle-resolution quarter --particle-tile-groups 16
  for p in sparks dust; do
    r $p-kf-$rep $N --particles $p --particle-lighting atlas --particle-count 65536
    r $p-mq-$rep $N --particles $p --particle-lighting vertex --particle-count 1000000 --particle-resolution quarter
  done
  echo rep $rep $SECONDS
done
cd $OUT && tar cJf r.tar.xz r tests.log && tar cf img.tar img && rm -rf r img tests.log; ls -la; true
