#!/usr/bin/env bash
# 2026-12-05 (second H200 run of the day): main's tip (base, 83e950b) against the branch's texture
# skip (t1), the compact-only walk probe (c1) and n1, which compiles the link format and the
# texture transforms into the passes as specialization constants (kLinkFormat, common/lll_data.glsl;
# kSceneHasTextureTransforms, common/visibility_surface.glsl). `lll render --frames 200 --stats`,
# three runs in rotating order; images of base and n1 kept. Then n1's `bench --suite threel`
# (shade-opaque against the ALU probe in the same run) and the GPU image suite with validation.
# Pack: pack.sh /tmp/lll_base /tmp/lll_t1 /tmp/lll_c1 /tmp/lll_n1 build/tests/lll_tests /tmp/layers
# (.gpu/bin/lll_base renamed lll), ../gpu-setup.sh as .gpu/setup.sh. PART=renders|bench|tests.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
bin() { case $1 in base) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
one() {  # variant rep name args...
  local v=$1 rep=$2 name=$3; shift 3
  local I=/tmp/a.png; [ $rep = 1 ] && case $v in base|n1) I=$OUT/img/$v-$name.png;; esac
  timeout 60 $(bin $v) render "$@" ${SIZE:-$W} --frames 200 --stats $OUT/r/$v-$name-$rep.json --out $I >/dev/null 2>&1 || echo fail $v $name
}
if [ "${PART:-renders}" = renders ]; then
  for v in base t1 c1 n1; do
    echo "== $v"; LLL_SHADER_STATS=1 timeout 60 $(bin $v) render threel16 --technique lll --width 64 --height 64 --frames 1 --out /tmp/b.png 2>&1 | grep -i "shade_visibility" | head -2
  done
  for rep in 1 2 3; do
    case $rep in 1) order="base t1 c1 n1";; 2) order="n1 c1 t1 base";; 3) order="t1 n1 base c1";; esac
    for v in $order; do
      one $v $rep threel16 threel16 --technique lll
      one $v $rep threel256 threel256 --technique lll
      SIZE="--width 3840 --height 2160" one $v $rep threel16-4k threel16 --technique lll
      case $v in c1) ;; *) one $v $rep atrium1024 atrium --lights 1024 --technique lll;; esac
      case $v in base|n1) one $v $rep forward16 threel16 --technique forward; one $v $rep forward256 threel256 --technique forward;; esac
    done
  done
  echo renders $SECONDS
fi
if [ "${PART:-renders}" = bench ]; then
  timeout 400 $E/lll_n1 bench --suite threel --technique lll --frames 20 --warmup 5 --out $OUT/bench-n1 >/dev/null 2>&1 || echo fail bench
  echo bench $SECONDS
fi
if [ "${PART:-renders}" = tests ]; then
  LLL_TEST_VALIDATION=1 timeout 500 $E/lll_tests --gtest_brief=1 ${FILTER:+--gtest_filter=$FILTER} > $OUT/tests.log 2>&1; echo "tests rc $?"
  grep -E "FAILED|PASSED|dB" $OUT/tests.log | grep -E "FAILED|PASSED|^\[ image" | tail -5
  echo tests $SECONDS
fi
cd $OUT && tar cJf r.tar.xz r $(ls -d bench-n1 2>/dev/null) $(ls tests.log 2>/dev/null) && tar cf img.tar img && rm -rf r img bench-n1; ls -la; true
