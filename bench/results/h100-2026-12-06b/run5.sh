#!/usr/bin/env bash
# Issue 11, 2026-12-06 (eighth session), the change to land: lll's opaque shading reads listed
# lights' records from a uniform block (--lll-records, auto: uniform on a GPU where <= 256 lights)
# and bounds a compact walk by the constant 256. base (53300cd); ubo (run3's experiment binary);
# fin (.gpu/bin/lll, the change as committed); finlod (fin + the level of detail computed in the
# shader and sampled with textureLod where LLL_LOD is set, not landed). lll render --frames 200
# --stats at 1080p, two runs in rotating order; the GPU image suite with validation on fin; then
# lll bench --suite threel --technique lll (the ALU probe) in the time left.
set -u
source .gpu/setup.sh
E=.gpu/extra
mkdir -p $OUT/r
run() {
  local v=$1; shift
  case $v in
    base) timeout 60 $E/lll_base "$@";;
    ubo) timeout 60 $E/lll_ubo "$@";;
    fin) timeout 60 .gpu/bin/lll "$@";;
    finlod) LLL_LOD=1 timeout 60 $E/lll_finlod "$@";;
  esac
}
cases=("threel16|lll|" "threel256|lll|" "atrium|lll|--lights 1024" "threel16|forward|")
for rep in 1 2; do
  case $rep in 1) order="base ubo fin finlod";; 2) order="finlod fin ubo base";; esac
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
LLL_SHADER_STATS=1 run fin render threel16 --technique lll --width 1920 --height 1080 --frames 3 --out /tmp/a.png 2>&1 | grep shade_visibility > $OUT/r/stats-fin.txt
mkdir -p $OUT/img
run fin render threel16 --technique lll --width 960 --height 540 --out $OUT/img/fin-threel16-lll.png >/dev/null 2>&1
run finlod render threel16 --technique lll --width 960 --height 540 --out $OUT/img/finlod-threel16-lll.png >/dev/null 2>&1
FILTER='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*:Layering.*:EnumNames.*'
mkdir -p build/tests && cp .gpu/bin/lll build/lll
left=$((420 - SECONDS)); echo "tests get $left s"
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_brief=1 --gtest_filter="$FILTER" > $OUT/r/tests.log 2>&1; echo "tests rc $? $SECONDS"
grep -E "FAILED|PASSED" $OUT/r/tests.log | tail -8
left=$((465 - SECONDS)); echo "bench gets $left s"
[ $left -gt 10 ] && timeout $left .gpu/bin/lll bench --suite threel --technique lll --frames 30 --warmup 3 --out $OUT/r/bench-fin > $OUT/r/bench.log 2>&1; echo "bench rc $? $SECONDS"
rm -f $OUT/r/bench-fin/*.png $OUT/r/bench-fin/*.svg
cd $OUT && tar cJf r.tar.xz r && rm -rf r && mv img/* . && rmdir img; ls -la; true
