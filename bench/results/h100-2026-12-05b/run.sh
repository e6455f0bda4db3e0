#!/usr/bin/env bash
# Issue 11, 2026-12-05 (fifth): main's tip (base) against p (two pixels an invocation in the
# opaque pass, their shared lists walked once), pr (p + readonly restrict buffers), r (restrict
# alone), u (a subgroup-uniform list walk). `lll render --frames 200 --stats` at 1080p, three runs
# in rotating order; then `bench --suite threel --technique lll` for base and p (ALU probe in the
# same run).
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r $OUT/img
bin() { case $1 in base) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
cases=("threel16|lll|" "threel256|lll|" "atrium|lll|--lights 1024" "threel16|lll|--tile 4" "threel256|tiled|" "threel256|forward|")
for rep in 1 2 3; do
  case $rep in 1) order="base p pr r u";; 2) order="u r pr p base";; 3) order="pr base u p r";; esac
  for v in $order; do
    for c in "${cases[@]}"; do
      IFS='|' read -r scene tech extra <<< "$c"
      name="$v-$scene-$tech$(echo $extra | tr -d ' -')-$rep"
      img=/tmp/a.png
      if [ $rep = 1 ] && { [ $v = base ] || [ $v = p ]; }; then img=$OUT/img/${name%-1}.png; fi
      timeout 60 $(bin $v) render $scene --technique $tech $extra --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$name.json --out $img >/dev/null 2>&1 || echo fail $name
    done
  done
  echo rep $rep $SECONDS
done
for v in base p; do
  timeout 150 $(bin $v) bench --suite threel --technique lll --frames 20 --warmup 5 --out $OUT/bench-$v >/dev/null 2>&1 || echo fail bench $v
done
echo done $SECONDS
cd $OUT && tar cJf r.tar.xz r bench-base bench-p && tar cf img.tar img && rm -rf r bench-base bench-p img; ls -la; true
