#!/usr/bin/env bash
# Issue 11, 2026-12-06 (ninth session), as it ran on an H100. base (main 82623dd); mirror
# (mesh.vert takes the mirror sign from the normal matrix's w); gu (mirror + glass and the G-buffer
# shading reading listed records through lightRecord, so lll's uniform block serves them too:
# gu-glass-gbuffer-records.patch); acc (.gpu/bin/lll: gu + every loop over lights, the opaque
# shading, glass, the G-buffer shading and the ALU probe, summing each light's colour times three
# scalar weights, the surface's colours applied once after it: acc-light-sums.patch, on gu).
# lll render --frames 200 --stats at 1080p, two runs in rotating order; shader statistics; the GPU
# image suite with validation on acc's tree; then lll bench --suite threel --technique lll on acc.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
run() {
  local v=$1; shift
  case $v in
    base) timeout 60 $E/lll_base "$@";;
    mirror) timeout 60 $E/lll_mirror "$@";;
    gu) timeout 60 $E/lll_gu "$@";;
    acc) timeout 60 .gpu/bin/lll "$@";;
  esac
}
cases=("threel16|lll|" "threel256|lll|" "threel16|lll|--surfaces gbuffer" "atrium|lll|--lights 1024" "threel16|forward|")
for rep in 1 2; do
  case $rep in 1) order="base mirror gu acc";; 2) order="acc gu mirror base";; esac
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
for v in base acc; do
  LLL_SHADER_STATS=1 run $v render threel16 --technique lll --width 1920 --height 1080 --frames 3 --out /tmp/a.png > $OUT/r/stats-$v.txt 2>&1
done
mkdir -p $OUT/img
run acc render threel256 --technique lll --width 960 --height 540 --out $OUT/img/acc-threel256-lll.png >/dev/null 2>&1
run base render threel256 --technique lll --width 960 --height 540 --out $OUT/img/base-threel256-lll.png >/dev/null 2>&1
FILTER='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*:Layering.*:EnumNames.*'
mkdir -p build/tests && cp .gpu/bin/lll build/lll
left=$((480 - SECONDS)); echo "tests get $left s"
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_brief=1 --gtest_filter="$FILTER" > $OUT/r/tests.log 2>&1; echo "tests rc $? $SECONDS"
grep -E "FAILED|PASSED" $OUT/r/tests.log | tail -8
left=$((560 - SECONDS)); echo "bench gets $left s"
[ $left -gt 10 ] && timeout $left .gpu/bin/lll bench --suite threel --technique lll --frames 30 --warmup 3 --out $OUT/r/bench-acc > $OUT/r/bench.log 2>&1; echo "bench rc $? $SECONDS"
rm -f $OUT/r/bench-acc/*.png $OUT/r/bench-acc/*.svg
cd $OUT && tar cJf r.tar.xz r && rm -rf r && mv img/* . && rmdir img; ls -la; true
