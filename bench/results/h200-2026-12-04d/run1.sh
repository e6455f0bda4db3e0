# run1: particles-composite joining a tile's small cells into one sorted run of up to 256 (batch:
# the working tree of this run), and with particles-bin's scatter asking four cursors at a time
# (s4), against 0a2c859 (base): the smoke bench of each; a million smoke particles at full
# resolution with 1, 2, 4, 8, 16 tile groups (batch, `lll render --stats`, two runs), 65,536 with
# 1 and 2; the particle tests on batch's tests binary with validation.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in batch) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361 --particles smoke --particle-lighting vertex"
for v in base batch s4; do
  timeout 150 $(bin $v) bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-$v > $OUT/bench-$v.log 2>&1; echo bench $v rc=$? $SECONDS
done
for rep in 1 2; do
  for g in 1 2 4 8 16; do r batch-m$g-$rep .gpu/bin/lll $S --particle-count 1000000 --particle-tile-groups $g --out /tmp/a.png; done
  for g in 1 2; do r batch-k$g-$rep .gpu/bin/lll $S --particle-count 65536 --particle-tile-groups $g --out /tmp/a.png; done
done
echo renders $SECONDS
left=$((560 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:SoftParticles.*:SmokeInOtherTechniques.*:*SmokeMatchesForward*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-* *.log && rm -rf r bench-* *.log; ls -la; true
