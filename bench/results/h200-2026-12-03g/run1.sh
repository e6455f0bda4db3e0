# run1: the bitonic sort's global steps four at a time in blocks of 4,096, particles-merge (the tile
# groups combined once, not in every resolve read), the bin's tiles row by row along the disc, and
# the composite's longest-cell atomic only where it raises the value (new) against c9f7042 (old)
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
N=.gpu/bin/lll; O=.gpu/extra/lll_head; E=.gpu/extra
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 200 $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*' > $OUT/tests.txt 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|image" $OUT/tests.txt | head -40
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  local img=/tmp/a.png; case $n in *-1) img=$OUT/img/$n.png;; esac
  timeout 90 $bin render atrium --lights 256 --particle-render compute --technique lll --width 1920 --height 1080 --frames 361 "$@" --stats $OUT/r/$n.json -o $img >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
for rep in 1 2; do
  for v in new old; do
    B=$N; [ $v = old ] && B=$O
    r $v-sparks-vertex-kf-$rep $B --particles sparks --particle-lighting vertex --particle-count 65536
    r $v-smoke-vertex-kf-$rep $B --particles smoke --particle-lighting vertex --particle-count 65536
    r $v-smoke-vertex-mh-$rep $B --particles smoke --particle-lighting vertex --particle-count 1000000 --particle-resolution half
  done
  echo rep $rep $SECONDS
done
for v in new old; do
  B=$N; [ $v = old ] && B=$O
  timeout 170 $B bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --out $OUT/$v > $OUT/$v.log 2>&1; echo $v rc=$? $SECONDS
done
cd $OUT && tar cJf r.tar.xz r new old new.log old.log tests.txt && tar cf img.tar img && rm -rf r img new old new.log old.log; ls -la; true
