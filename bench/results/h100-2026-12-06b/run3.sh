#!/usr/bin/env bash
# Issue 11, 2026-12-06 (eighth session): a compact list's light records read from a uniform block
# (the constant cache) instead of the storage buffer. base (53300cd, .gpu/extra/lll_base); ubo
# (.gpu/bin/lll); ubo0 (the same binary with LLL_UBO=0: the records from the storage buffer).
# lll render --frames 200 --stats at 1080p, three runs in rotating order; shader stats; images;
# the GPU image suite with validation with the uniform records, if ubo was faster at threel16.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
run() { local v=$1; shift; case $v in base) timeout 60 $E/lll_base "$@";; ubo) timeout 60 .gpu/bin/lll "$@";; ubo0) LLL_UBO=0 timeout 60 .gpu/bin/lll "$@";; esac; }
cases=("threel16|lll|" "threel256|lll|" "atrium|lll|--lights 1024" "threel16|lll|--tile 8" "threel16|forward|")
for rep in 1 2 3; do
  case $rep in 1) order="base ubo ubo0";; 2) order="ubo0 ubo base";; 3) order="ubo base ubo0";; esac
  for v in $order; do
    for c in "${cases[@]}"; do
      IFS='|' read -r scene tech extra <<< "$c"
      name="$v-$scene-$tech$(echo $extra | tr -d ' -')-$rep"
      run $v render $scene --technique $tech $extra --width 1920 --height 1080 --frames 200 \
        --stats $OUT/r/$name.json --out /tmp/a.png >/dev/null 2>&1 || echo fail $name
    done
  done
  echo rep $rep $SECONDS
done
for v in base ubo ubo0; do
  LLL_SHADER_STATS=1 run $v render threel16 --technique lll --width 1920 --height 1080 --frames 3 --out /tmp/a.png 2>&1 | grep shade_visibility > $OUT/r/stats-$v.txt
done
mkdir -p $OUT/img
run ubo render threel256 --technique lll --width 960 --height 540 --out $OUT/img/ubo-threel256-lll.png >/dev/null 2>&1
run base render threel256 --technique lll --width 960 --height 540 --out $OUT/img/base-threel256-lll.png >/dev/null 2>&1
med() { for f in $OUT/r/$1-threel16-lll-*.json; do grep -B3 '"shade-opaque"' $f | grep median_ms | tr -dc '0-9.\n'; done | sort -n | sed -n 2p; }
b=$(med base); u=$(med ubo); echo "threel16 shade-opaque base $b ubo $u"
if awk -v u="$u" -v b="$b" 'BEGIN { exit !(u < 0.98 * b) }'; then
  FILTER='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*:Layering.*:EnumNames.*'
  mkdir -p build/tests && cp .gpu/bin/lll build/lll
  left=$((580 - SECONDS)); echo "tests get $left s"
  LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_brief=1 --gtest_filter="$FILTER" > $OUT/r/tests.log 2>&1; echo "tests rc $?"
  grep -E "FAILED|PASSED" $OUT/r/tests.log | tail -8
fi
cd $OUT && tar cJf r.tar.xz r && rm -rf r && mv img/* . && rmdir img; ls -la; true
