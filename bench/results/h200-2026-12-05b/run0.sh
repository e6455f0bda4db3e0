# For the next GPU session (issue 11): main's tip (base) against this branch's texture skip (t1)
# and the walk probes (q1, q3: links read ahead down a segment; c1: compact links only; q1c both;
# variants.sh builds them). `lll render --frames 200 --stats`, 1080p (threel16 also 4K), three runs
# in rotating order; c1 and q1c only on ThreeL (at most 256 lights: compact links). Registers of
# the shading pass (LLL_SHADER_STATS); images of base and t1 kept to compare. t2 is t1's binary with
# LLL_PROBE_COMPUTED_LOD=1: the rebuild computes the level of detail and samples with textureLod (as
# on lavapipe) instead of textureGrad; its image is kept too (it may differ from forward's). Last,
# t1's `bench --suite threel`, whose alu-probe-half row says what packed 16-bit arithmetic could
# take off the 256-light floor (bench/README.md, 2026-12-04 (fifth)).
# Pack: pack.sh /tmp/lll_base /tmp/lll_t1 /tmp/lll_q1 /tmp/lll_q3 /tmp/lll_c1 /tmp/lll_q1c /tmp/layers
# (then .gpu/bin/lll_base renamed lll), ../gpu-setup.sh as .gpu/setup.sh.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
bin() { case $1 in base) echo .gpu/bin/lll;; t2) echo $E/lll_t1;; *) echo $E/lll_$1;; esac; }
W="--width 1920 --height 1080"
one() {  # variant rep name args...
  local v=$1 rep=$2 name=$3; shift 3
  local I=/tmp/a.png; [ $rep = 1 ] && case $v-$name in base-threel16|t1-threel16|t2-threel16|base-atrium1024|t1-atrium1024) I=$OUT/img/$v-$name.png;; esac
  [ $v = t2 ] && export LLL_PROBE_COMPUTED_LOD=1 || unset LLL_PROBE_COMPUTED_LOD
  timeout 60 $(bin $v) render "$@" ${SIZE:-$W} --frames 200 --stats $OUT/r/$v-$name-$rep.json --out $I >/dev/null 2>&1 || echo fail $v $name
}
[ "${STATS:-1}" = 1 ] && for v in base t1 q1 q3 c1 q1c; do
  echo "== $v"; LLL_SHADER_STATS=1 timeout 60 $(bin $v) render threel16 --technique lll --width 64 --height 64 --frames 1 --out /tmp/b.png 2>&1 | grep -i "shade_visibility\|registers" | head -4
done
for rep in ${REPS:-1 2 3}; do
  case $rep in 1) order="base t1 t2 q1 q3 c1 q1c";; 2) order="q1c c1 q3 q1 t2 t1 base";; 3) order="q1 base t2 q1c t1 c1 q3";; esac
  for v in $order; do
    one $v $rep threel16 threel16 --technique lll
    one $v $rep threel256 threel256 --technique lll
    SIZE="--width 3840 --height 2160" one $v $rep threel16-4k threel16 --technique lll
    case $v in c1|q1c) ;; *) one $v $rep atrium1024 atrium --lights 1024 --technique lll;; esac
    case $v in base|t1|t2) one $v $rep forward16 threel16 --technique forward;; esac
  done
done
echo renders $SECONDS
# The ALU probe in 32 and in packed 16-bit floats (alu-probe, alu-probe-half) beside ThreeL's frames.
[ "${BENCH:-1}" = 1 ] && timeout 400 $E/lll_t1 bench --suite threel --technique lll --frames 20 --warmup 5 --out $OUT/bench-t1 >/dev/null 2>&1 || echo fail bench
echo bench $SECONDS
cd $OUT && tar cJf r.tar.xz r $(ls -d bench-t1 2>/dev/null) && tar cf img.tar img && rm -rf r img bench-t1; ls -la; true
