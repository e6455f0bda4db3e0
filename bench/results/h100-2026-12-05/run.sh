#!/usr/bin/env bash
# For the next GPU session (issue 11's 2x at 16 lights): main's tip (base) against the probes
# variants.sh builds (r1 no lights, r2 no textures, r3 no display store, r13 r1 and r3), ThreeL 16
# and 256 lights at 1080p, `lll render --frames 200 --stats`, three runs in rotating order; then
# base's `bench --suite threel` for the ALU probe of the same run. PART=tests: the GPU image suite
# with validation on main's tip (its tests built there: the enum settings, reflected layouts and
# descriptor types of the third session of 2026-12-05 and the kept light staging of the fourth have
# not run on a GPU), FILTER as README's GPU filter. PART=moving: the moving suite's lll rows.
# Pack: pack.sh /tmp/lll_base /tmp/lll_r1 /tmp/lll_r2 /tmp/lll_r3 /tmp/lll_r13 build/tests/lll_tests
# /tmp/layers (.gpu/bin/lll_base renamed lll; lll_tests built on main), ../gpu-setup.sh as
# .gpu/setup.sh; the tests need build/lll there (mkdir -p build/tests; cp .gpu/bin/lll build/lll).
# About 60 s of renders, 330 s of tests.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
bin() { case $1 in base) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
if [ "${PART:-renders}" = moving ]; then
  # The CPU's light placement and upload of 9ebc031 (bench/README.md, "CPU only, 2026-12-05
  # (third)") on the H200's 16 cores: the cpu-motion rows' light-update-cpu-ms, against
  # results/h200-2026-12-05/ (before it).
  timeout 500 .gpu/bin/lll bench --suite moving --technique lll --frames 15 --warmup 5 --out $OUT/bench-moving \
    > $OUT/bench-moving.log 2>&1; echo "bench rc $?"
  cd $OUT && tar cJf moving.tar.xz bench-moving bench-moving.log && rm -rf bench-moving bench-moving.log; ls -la; exit 0
fi
if [ "${PART:-renders}" = tests ]; then
  LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 500 $E/lll_tests --gtest_brief=1 ${FILTER:+--gtest_filter=$FILTER} \
    > $OUT/tests.log 2>&1; echo "tests rc $?"
  grep -E "FAILED|PASSED" $OUT/tests.log | tail -5
  cd $OUT && xz tests.log; ls -la; exit 0
fi
for rep in 1 2 3; do
  case $rep in 1) order="base r1 r2 r3 r13";; 2) order="r13 r3 r2 r1 base";; 3) order="r2 base r13 r1 r3";; esac
  for v in $order; do
    for s in threel16 threel256; do
      timeout 60 $(bin $v) render $s --technique lll --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$v-$s-$rep.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $v $s
    done
  done
done
echo renders $SECONDS
timeout 200 .gpu/bin/lll bench --suite threel --technique lll --frames 20 --warmup 5 --out $OUT/bench-base >/dev/null 2>&1 || echo fail bench
cd $OUT && tar cJf r.tar.xz r bench-base && rm -rf r bench-base; ls -la; true
