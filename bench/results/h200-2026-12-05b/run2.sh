#!/usr/bin/env bash
# 2026-12-05 (second run, last call): n1 (run1's) against n2, whose surface rebuild reads a
# vertex as 16-byte vectors (three, four with TEXCOORD_1 or COLOR_0) instead of 12 to 16 words,
# n3 (n2 taking the three vertices' attributes one vertex after another, after the barycentrics,
# so one vertex's are live at a time), and n1 with one list per tile (s1: --lll-slices 1). Three runs in rotating order, then n2's
# `bench --suite threel`. Pack: pack.sh /tmp/lll_n1 /tmp/lll_n2 /tmp/lll_n3 /tmp/layers (.gpu/bin/lll_n1).
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
bin() { case $1 in n1|s1) echo .gpu/bin/lll_n1;; *) echo $E/lll_$1;; esac; }
one() {  # variant rep name args...
  local v=$1 rep=$2 name=$3; shift 3
  local extra=; [ $v = s1 ] && extra="--lll-slices 1"
  timeout 60 $(bin $v) render "$@" $extra --width 1920 --height 1080 --frames 200 --stats $OUT/r/$v-$name-$rep.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $v $name
}
for v in n1 n2 n3; do
  echo "== $v"; LLL_SHADER_STATS=1 timeout 60 $(bin $v) render threel16 --technique lll --width 64 --height 64 --frames 1 --out /tmp/b.png 2>&1 | grep -i "shade_visibility" | head -2
done
for rep in 1 2 3; do
  case $rep in 1) order="n1 n2 n3 s1";; 2) order="s1 n3 n2 n1";; 3) order="n3 n1 s1 n2";; esac
  for v in $order; do
    one $v $rep threel16 threel16 --technique lll
    one $v $rep threel256 threel256 --technique lll
    one $v $rep atrium1024 atrium --lights 1024 --technique lll
  done
done
echo renders $SECONDS
timeout 200 $(bin ${BEST:-n3}) bench --suite threel --technique lll --frames 20 --warmup 5 --out $OUT/bench-best >/dev/null 2>&1 || echo fail bench
echo bench $SECONDS
cd $OUT && tar cJf r.tar.xz r bench-best && rm -rf r bench-best; ls -la; true
