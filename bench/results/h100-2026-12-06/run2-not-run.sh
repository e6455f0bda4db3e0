#!/usr/bin/env bash
# Issue 11, 2026-12-06: why the group walk (g, run1) took 96 registers. base (f9824fe); g2, the
# group walk over both of a tile's lists (no per-point walk needed where the tile holds the
# workgroup); n, g2 with the per-point walk compiled out; u, g2 with the chunk loop not unrolled;
# nu, both. Binaries: main + g-group-walk.patch + g2-on-g-two-lists.patch is g2; n, u and nu
# add `#define EXP_NOFALLBACK` / `#define EXP_NOUNROLL` as the first lines of
# shaders/lit/shade_visibility.comp.glsl; packed as .gpu/extra/lll_{base,g2,n,u,nu}.
# lll render --frames 200 --stats at 1080p, two runs in rotating order; shader stats.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
cases=("threel16|lll|" "threel256|lll|" "atrium|lll|--lights 1024")
for rep in 1 2; do
  case $rep in 1) order="base g2 n u nu";; 2) order="nu u n g2 base";; 3) order="n base nu g2 u";; esac
  for v in $order; do
    for c in "${cases[@]}"; do
      IFS='|' read -r scene tech extra <<< "$c"
      name="$v-$scene-$tech$(echo $extra | tr -d ' -')-$rep"
      timeout 60 $E/lll_$v render $scene --technique $tech $extra --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$name.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $name
    done
  done
  echo rep $rep $SECONDS
done
for v in base g2 n u nu; do
  LLL_SHADER_STATS=1 $E/lll_$v render threel16 --technique lll --width 1920 --height 1080 --frames 3 --out /tmp/a.png 2>&1 | grep shade_visibility > $OUT/r/stats-$v.txt
done
cd $OUT && tar cJf r.tar.xz r && rm -rf r; ls -la; true
