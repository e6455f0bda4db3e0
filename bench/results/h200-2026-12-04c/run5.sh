# run5: particles-bin with 4, 8 or 16 invocations a particle, each taking every n-th row of its
# tiles (bin4, bin8, bin16), against one a particle (base, 4f2aebc): the smoke bench of each, base
# and bin8 twice; sparks and dust (65,536, atlas and vertex, full resolution) of bin8 and of 14a21ee
# (old), two runs; the particle tests on bin8's tests binary.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r $OUT/sparks $OUT/dust
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in bin8) echo .gpu/bin/lll;; old) echo $E/lll_old;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361"
for rep in 1 2; do for v in old bin8; do for p in sparks dust; do for l in atlas vertex; do
  I=/tmp/a.png; [ $rep = 1 ] && [ $l = atlas ] && I=$OUT/$p/$v-$p-$l.png
  r $v-$p-$l-$rep $(bin $v) $S --particles $p --particle-lighting $l --particle-count 65536 --out $I
done; done; done; done
echo renders $SECONDS
for v in base bin4 bin8 bin16 base bin8; do
  n=1; [ -d $OUT/bench-$v-1 ] && n=2
  timeout 150 $(bin $v) bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-$v-$n > $OUT/bench-$v-$n.log 2>&1; echo bench $v rc=$? $SECONDS
done
left=$((570 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:SoftParticles.*:SmokeInOtherTechniques.*:*SmokeMatchesForward*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-* *.log && tar cf sparks.tar sparks && tar cf dust.tar dust && rm -rf r sparks dust bench-* *.log; ls -la; true
