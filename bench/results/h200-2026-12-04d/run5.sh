# run5: a tile's groups from its particles (final2: the tree of this run) against ef6be62 (final):
# settled smoke at 1080p, 65,536 and a million, sparks and dust (65,536, atlas- and vertex-lit),
# `lll render --stats`, two runs; the smoke bench of final2; the particle tests on its tests binary
# with validation.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/r
r() { local n=$1 bin=$2; shift 2
  timeout 90 $bin render "$@" --stats $OUT/r/$n.json >/dev/null 2>$OUT/r/$n.err || { echo fail $n; tail -2 $OUT/r/$n.err; }; }
bin() { case $1 in final2) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
S="atrium --lights 256 --particle-render compute --technique lll $W --frames 361"
for rep in 1 2; do for v in final final2; do
  r $v-k65-$rep $(bin $v) $S --particles smoke --particle-lighting vertex --particle-count 65536 --out /tmp/a.png
  r $v-m1-$rep $(bin $v) $S --particles smoke --particle-lighting vertex --particle-count 1000000 --out /tmp/a.png
  for p in sparks dust; do for l in atlas vertex; do
    r $v-$p-$l-$rep $(bin $v) $S --particles $p --particle-lighting $l --particle-count 65536 --out /tmp/a.png
  done; done
done; done
echo renders $SECONDS
timeout 150 .gpu/bin/lll bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-final2 > $OUT/bench-final2.log 2>&1; echo bench rc=$? $SECONDS
left=$((560 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:SoftParticles.*:SmokeInOtherTechniques.*:*SmokeMatchesForward*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -10; grep -c "^\[       OK" $OUT/tests.log
cd $OUT && tar cJf r.tar.xz r bench-* *.log && rm -rf r bench-* *.log; ls -la; true
