// glTF loader tests, broken input: each file must end in an InputError whose message names it
// (and, where it matters, what is wrong), never in a crash or a partial scene.
#include "gltf_test_support.h"

namespace lll {
namespace {

using namespace gltf_test;  // the files' builder and checks (gltf_test_support.h)

TEST_F(GltfLoaderTest, MissingFileIsInputError) {
  expectInputError(dir_ / "nowhere.gltf", "not found");
}

TEST_F(GltfLoaderTest, EmptyFileIsInputError) {
  writeText(dir_ / "empty.gltf", "");
  expectInputError(dir_ / "empty.gltf", "empty");
}

TEST_F(GltfLoaderTest, PngIsNotGltf) {
  writeBytes(dir_ / "picture.gltf", kPng2x2.data(), kPng2x2.size());
  expectInputError(dir_ / "picture.gltf");
}

TEST_F(GltfLoaderTest, RandomBytesAreNotGltf) {
  std::mt19937 random(7);
  std::vector<uint8_t> noise(4096);
  for (uint8_t& byte : noise) byte = uint8_t(random());
  writeBytes(dir_ / "noise.glb", noise.data(), noise.size());
  expectInputError(dir_ / "noise.glb");
  noise[0] = 'g', noise[1] = 'l', noise[2] = 'T', noise[3] = 'F';  // a GLB header over noise
  writeBytes(dir_ / "fakeheader.glb", noise.data(), noise.size());
  expectInputError(dir_ / "fakeheader.glb");
}

TEST_F(GltfLoaderTest, InvalidJsonIsInputError) {
  writeText(dir_ / "broken.gltf", R"({"asset": {"version": "2.0"}, "meshes": [)");
  expectInputError(dir_ / "broken.gltf");
}

TEST_F(GltfLoaderTest, DeeplyNestedJsonIsInputError) {
  writeText(dir_ / "deep.gltf", R"({"asset": {"version": "2.0"}, "extras": )" + std::string(200000, '[') +
                                    std::string(200000, ']') + "}");
  expectInputError(dir_ / "deep.gltf", "nested");
}

TEST_F(GltfLoaderTest, GltfVersionOneIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["asset"]["version"] = "1.0";
  expectInputError(b.writeGltf(dir_, "old"), "1.0");
}

TEST_F(GltfLoaderTest, MissingBinIsInputError) {
  const fs::path path = quadScene().writeGltf(dir_, "nobin");
  fs::remove(dir_ / "nobin.bin");
  expectInputError(path, "nobin.bin");
}

TEST_F(GltfLoaderTest, TruncatedBinIsInputError) {
  const fs::path path = quadScene().writeGltf(dir_, "short");
  fs::resize_file(dir_ / "short.bin", 20);
  expectInputError(path, "short.bin");
}

TEST_F(GltfLoaderTest, TruncatedGlbIsInputError) {
  const fs::path path = quadScene().writeGlb(dir_, "cut");
  fs::resize_file(path, fs::file_size(path) - 40);
  expectInputError(path);
}

TEST_F(GltfLoaderTest, AccessorBeyondItsBufferViewIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["accessors"][0]["count"] = 5;  // the view holds 4 positions
  expectInputError(b.writeGltf(dir_, "count"), "bufferView");
  b.doc["accessors"][0]["count"] = 4;
  b.doc["accessors"][0]["byteOffset"] = 4;
  expectInputError(b.writeGltf(dir_, "offset"), "bufferView");
}

TEST_F(GltfLoaderTest, AbsurdAccessorCountIsInputErrorWithoutAllocating) {
  GltfBuilder b = quadScene();
  b.doc["accessors"][0]["count"] = uint64_t{1} << 61;  // count * 12 overflows 64 bits
  expectInputError(b.writeGltf(dir_, "huge"), "bufferView");
  b.doc["accessors"][0]["count"] = uint64_t{1} << 40;
  b.doc["accessors"][0].erase("bufferView");  // all zeros, nothing in the file bounds it
  expectInputError(b.writeGltf(dir_, "hugezeros"), "count");
}

TEST_F(GltfLoaderTest, BufferViewBeyondItsBufferIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["bufferViews"][3]["byteLength"] = 4096;
  expectInputError(b.writeGltf(dir_, "view"), "buffer 0");
}

TEST_F(GltfLoaderTest, ByteStrideSmallerThanElementIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["bufferViews"][0]["byteStride"] = 4;
  expectInputError(b.writeGltf(dir_, "stride"), "byteStride");
}

TEST_F(GltfLoaderTest, IndexOutOfRangeIsInputError) {
  GltfBuilder b = quadScene();
  const uint16_t bad = 4;  // the quad has vertices 0..3
  std::memcpy(&b.bin[b.accessorByteOffset[3] + 2], &bad, sizeof bad);
  expectInputError(b.writeGltf(dir_, "index"), "index 4");
}

TEST_F(GltfLoaderTest, WrongComponentTypeIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["accessors"][0]["componentType"] = kUnsignedShort;
  expectInputError(b.writeGltf(dir_, "component"), "POSITION");
  b.doc["accessors"][0]["componentType"] = kFloat;
  b.doc["accessors"][2]["componentType"] = kUnsignedByte;  // TEXCOORD_0 bytes, but not normalized
  expectInputError(b.writeGltf(dir_, "texcoord"), "TEXCOORD_0");
}

TEST_F(GltfLoaderTest, UnsupportedRequiredExtensionIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["extensionsUsed"] = {"KHR_texture_basisu"};
  b.doc["extensionsRequired"] = {"KHR_texture_basisu"};
  expectInputError(b.writeGltf(dir_, "basisu"), "KHR_texture_basisu");
}

TEST_F(GltfLoaderTest, SupportedRequiredExtensionsLoad) {
  GltfBuilder b = quadScene();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_ior"};
  b.doc["extensionsRequired"] = {"KHR_lights_punctual", "KHR_texture_transform", "KHR_materials_ior"};
  LoadReport report;
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "required"), &report).vertices.size(), 4u);
  EXPECT_FALSE(anyWarningContains(report, "KHR_texture_transform"));  // read (test_texture_transform.cpp)
  EXPECT_TRUE(anyWarningContains(report, "KHR_materials_ior"));       // ignored, with a warning
}

TEST_F(GltfLoaderTest, MeshWithoutPositionIsInputError) {
  GltfBuilder b = quadScene();
  b.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  expectInputError(b.writeGltf(dir_, "noposition"), "POSITION");
}

TEST_F(GltfLoaderTest, BadReferencesAreInputErrors) {
  GltfBuilder b = quadScene();
  b.doc["nodes"][0]["mesh"] = 3;
  expectInputError(b.writeGltf(dir_, "meshref"), "mesh 3");
  b.doc["nodes"][0]["mesh"] = 0;
  b.doc["meshes"][0]["primitives"][0]["material"] = 9;
  expectInputError(b.writeGltf(dir_, "materialref"), "material 9");
  b.doc["meshes"][0]["primitives"][0]["material"] = 0;
  b.doc["nodes"] = json::array({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}});
  expectInputError(b.writeGltf(dir_, "cycle"), "node 0");
}

}  // namespace
}  // namespace lll
