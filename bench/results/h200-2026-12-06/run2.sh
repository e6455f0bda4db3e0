#!/usr/bin/env bash
# Issue 11, 2026-12-06 (eighth session): why the group walk (g, run1) took 96 registers, and links
# read as one 8-byte load. base (53300cd); g2, the group walk over both of a tile's lists; n, g2
# with the per-point walk compiled out; u, g2 with the chunk loop not unrolled; nu, both (binaries
# as run2-not-run.sh says); pair (.gpu/bin/lll), main with the link pool declared as uvec2 pairs.
# lll render --frames 200 --stats at 1080p, two runs in rotating order; shader stats; pair's
# images; the GPU image suite with validation on pair.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
bin() { case $1 in pair) echo .gpu/bin/lll;; *) echo $E/lll_$1;; esac; }
cases=("threel16|lll|" "threel256|lll|" "atrium|lll|--lights 1024")
for rep in 1 2; do
  case $rep in 1) order="base pair g2 n u nu";; 2) order="nu u n g2 pair base";; esac
  for v in $order; do
    for c in "${cases[@]}"; do
      IFS='|' read -r scene tech extra <<< "$c"
      name="$v-$scene-$tech$(echo $extra | tr -d ' -')-$rep"
      timeout 60 $(bin $v) render $scene --technique $tech $extra --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$name.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $name
    done
  done
  echo rep $rep $SECONDS
done
for v in base pair g2 n u nu; do
  LLL_SHADER_STATS=1 $(bin $v) render threel16 --technique lll --width 1920 --height 1080 --frames 3 --out /tmp/a.png 2>&1 | grep -i -A3 shade_visibility > $OUT/r/stats-$v.txt
done
mkdir -p $OUT/img
.gpu/bin/lll render threel16 --technique lll --width 960 --height 540 --out $OUT/img/pair-threel16-lll.png >/dev/null 2>&1
.gpu/bin/lll render atrium --lights 1024 --technique lll --lll-link wide --width 960 --height 540 --out $OUT/img/pair-atrium-wide.png >/dev/null 2>&1
FILTER='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*:Layering.*:EnumNames.*'
mkdir -p build/tests && cp .gpu/bin/lll build/lll
left=$((580 - SECONDS)); echo "tests get $left s"
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_brief=1 --gtest_filter="$FILTER" > $OUT/r/tests.log 2>&1; echo "tests rc $?"
grep -E "FAILED|PASSED" $OUT/r/tests.log | tail -8
cd $OUT && tar cJf r.tar.xz r && rm -rf r && mv img/* . && rmdir img; ls -la; true
