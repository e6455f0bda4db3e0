#!/usr/bin/env bash
# Issue 11, 2026-12-05 (sixth): base (f9824fe) against g, the workgroup's list walked 64 links a
# round into shared memory (lighting/lll/lighting.glsl nextGroupLights). lll render --frames 200
# --stats at 1080p, three runs in rotating order (gall: the group walk with every fill, shells and
# ray); shader statistics; g's images; the GPU image suite with validation, time permitting.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
bin() { case $1 in base) echo $E/lll_base;; gall) echo $E/lll_gall;; *) echo .gpu/bin/lll;; esac; }
cases=("threel16|lll|" "threel256|lll|" "atrium|lll|--lights 1024" "threel16|lll|--tile 8" "threel16|lll|--lll-fill shells" "threel16|forward|")
for rep in 1 2 3; do
  case $rep in 1) order="base g";; 2) order="g base";; 3) order="base g";; esac
  for v in $order; do
    for c in "${cases[@]}"; do
      IFS='|' read -r scene tech extra <<< "$c"
      name="$v-$scene-$tech$(echo $extra | tr -d ' -')-$rep"
      timeout 60 $(bin $v) render $scene --technique $tech $extra --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$name.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $name
    done
  done
  for c in "threel16|lll|--lll-fill shells" "threel16|lll|--lll-fill ray"; do
    IFS='|' read -r scene tech extra <<< "$c"
    for v in gall base; do
      name="$v-$scene-$tech$(echo $extra | tr -d ' -')-$rep"
      timeout 60 $(bin $v) render $scene --technique $tech $extra --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$name.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $name
    done
  done
  echo rep $rep $SECONDS
done
for v in base g; do
  LLL_SHADER_STATS=1 $(bin $v) render threel16 --technique lll --width 1920 --height 1080 --frames 3 --out /tmp/a.png > $OUT/r/stats-$v.txt 2>&1
done
mkdir -p $OUT/img
.gpu/bin/lll render threel256 --technique lll --width 960 --height 540 --out $OUT/img/g-threel256-lll.png >/dev/null 2>&1
.gpu/bin/lll render atrium --lights 1024 --technique lll --width 960 --height 540 --out $OUT/img/g-atrium-lll.png >/dev/null 2>&1
$E/lll_base render atrium --lights 1024 --technique lll --width 960 --height 540 --out $OUT/img/base-atrium-lll.png >/dev/null 2>&1
FILTER='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*:Layering.*:EnumNames.*'
mkdir -p build/tests && cp .gpu/bin/lll build/lll
left=$((575 - SECONDS)); echo "tests get $left s"
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_brief=1 --gtest_filter="$FILTER" > $OUT/r/tests.log 2>&1; echo "tests rc $?"
grep -E "FAILED|PASSED" $OUT/r/tests.log | tail -5
cd $OUT && tar cJf r.tar.xz r && rm -rf r && mv img/* . && rmdir img; ls -la; true
