# For the next GPU session, first: main's GPU image suite with validation, which has not run on the
# H200 since the link-at-a-time walk (5be8d9e), nor on what landed 2026-12-04 without a GPU (mirrored
# glTF nodes, lights-move, the quantized and compressed caves, data textures on lavapipe,
# KHR_texture_transform) and 2026-12-05 (the 64-byte vertex with TEXCOORD_1 and COLOR_0 as half
# floats read as bits in the surface rebuild, glTF samplers per texture: TextureCoordinates.*,
# VertexColors.*, TextureSamplers.*); then the moving suite (its million
# moving lights, GPU against CPU placement) and lights-move's positions against the CPU's.
# Pack from main's build: pack.sh build/lll build/tests/lll_tests /tmp/layers; ../gpu-setup.sh as
# .gpu/setup.sh. About 280 s of tests and 200 s of bench.
set -u
source .gpu/setup.sh
mkdir -p build/tests && cp .gpu/bin/lll build/lll
E=.gpu/extra
F='-*Soak*:*Viewer*:ViewCamera.*:InputScript.*:InstalledPackage.*:Bench*:HostileCli*:HostileGltf*:FuzzRegressions*:GltfLoaderTest*:Photons*:GiReferenceCli*:LightAnimationCli*:MeshBuilder*'
LLL_TEST_DEVICE=gpu LLL_TEST_VALIDATION=1 LLL_TEST_IMAGE_REPORT=$OUT/images.csv timeout 420 $E/lll_tests --gtest_filter="$F" > $OUT/tests.log 2>&1; echo tests rc=$? $SECONDS
grep -E "^\[  FAILED|PASSED" $OUT/tests.log | head -20; grep -c "^\[       OK" $OUT/tests.log
grep "GPU against CPU positions" $OUT/tests.log
timeout 240 .gpu/bin/lll bench --suite moving --frames 15 --warmup 5 --out $OUT/bench-moving > $OUT/bench-moving.log 2>&1; echo bench rc=$? $SECONDS
cd $OUT && tar cJf r.tar.xz bench-* *.log images.csv && rm -rf bench-* *.log images.csv; ls -la; true
