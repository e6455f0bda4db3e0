# run7: the GPU image suite except the particle tests (run6 ran those) at the landed tree (73b0214),
# with validation, and the default scene rendered at 1080p
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
timeout 60 .gpu/bin/lll render atrium --width 1920 --height 1080 -o $OUT/atrium.png > /dev/null 2>&1; echo render rc=$?
left=$((560 - SECONDS))
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 timeout $left $E/lll_tests --gtest_filter='-BitonicSort.*:ParticleSort.*:PuffNoise.*:ComputeParticles.*:*ComputeMatchesRaster*:GlassAndParticles.*:*ParticleLighting*:*Particle*Image*:*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*' > $OUT/tests-rest.log 2>&1; echo rest rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED|tests ran" $OUT/tests-rest.log | head; grep -c "^\[       OK" $OUT/tests-rest.log
cd $OUT && xz -T4 tests-rest.log; ls -la; true
