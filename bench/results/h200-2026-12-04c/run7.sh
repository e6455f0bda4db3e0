# run7: the landed tree (BRDF weights, one-read noise, packed staging, ParticleScreen 64 bytes, 8 bin
# lanes a particle at full resolution): the GPU image suite with validation, the smoke bench (65,536
# and a million) and the threel bench (lll, forward), settled smoke and ThreeL's 256 lights at 1080p.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
mkdir -p $OUT/img
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout 300 $E/lll_tests --gtest_filter='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
tail -3 $OUT/tests.log; grep -E "^\[  FAILED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
W="--width 1920 --height 1080"
timeout 60 .gpu/bin/lll render atrium --lights 256 --particle-render compute --technique lll $W --frames 361 --particles smoke --particle-lighting vertex --particle-count 65536 --out $OUT/img/smoke64k.png >/dev/null 2>&1 || echo render failed
timeout 30 .gpu/bin/lll render threel256 --technique lll $W --out $OUT/img/t256.png >/dev/null 2>&1 || echo render failed
timeout 100 .gpu/bin/lll bench --suite smoke --technique lll --particle-count 65536 --particle-count 1000000 --frames 15 --warmup 5 --out $OUT/bench-smoke > $OUT/bench-smoke.log 2>&1; echo bench smoke rc=$? $SECONDS
timeout 60 .gpu/bin/lll bench --suite threel --technique lll --technique forward --out $OUT/bench-threel > $OUT/bench-threel.log 2>&1; echo bench threel rc=$? $SECONDS
cd $OUT && xz -T4 tests.log && tar cJf r.tar.xz bench-* *.log && tar cf img.tar img && rm -rf bench-* img *.log; ls -la; true
