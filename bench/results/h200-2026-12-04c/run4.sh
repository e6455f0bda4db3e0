# run4: on top of pack (72ccb98): select (keyOfRank finds the rank's bit of a word in five halvings
# instead of dropping bits one at a time) and screen (select + ParticleScreen rearranged so the
# composite stages a particle with one 32-byte read and no packing; 80 -> 64 bytes): the smoke bench
# of each twice, interleaved; sparks and dust (65,536, atlas and vertex, full resolution) of screen
# and of 14a21ee (old); settled smoke frames; registers; the particle tests on screen's tests binary.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in screen) echo .gpu/bin/lll;; select) echo $E/lll_select;; pack) echo $E/lll_pack;; old) echo $E/lll_old;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361"
for v in pack screen; do
  LLL_SHADER_STATS=1 timeout 60 $(bin $v) render $S --particles smoke --particle-lighting vertex --particle-count 1000000 --out /tmp/a.png 2>&1 | grep -E "particles_tiles|bin.comp" > $OUT/r/$v-shader-stats.txt
  r $v-smoke64k $(bin $v) $S --particles smoke --particle-lighting vertex --particle-count 65536 --out $OUT/img/$v-smoke64k.png
  r $v-smoke1m $(bin $v) $S --particles smoke --particle-lighting vertex --particle-count 1000000 --out $OUT/img/$v-smoke1m.png
done
for rep in 1 2; do for v in old screen; do for p in sparks dust; do for l in atlas vertex; do
  I=/tmp/a.png; [ $rep = 1 ] && I=$OUT/img/$v-$p-$l.png
  r $v-$p-$l-$rep $(bin $v) $S --particles $p --particle-lighting $l --particle-count 65536 --out $I
done; done; done; done
echo renders $SECONDS
for rep in 1 2; do for v in pack select screen; do
  timeout 150 $(bin $v) bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-$v-$rep > $OUT/bench-$v-$rep.log 2>&1; echo bench $v rc=$? $SECONDS
done; done
left=$((570 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:SoftParticles.*:SmokeInOtherTechniques.*:*SmokeMatchesForward*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-* *.log && tar cf img1.tar img/pack-* img/screen-smoke* && tar cf img2.tar img/old-* img/screen-sparks* img/screen-dust* && rm -rf r img bench-* *.log; ls -la; true
