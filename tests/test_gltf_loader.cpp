// glTF loader tests: small files written per test (JSON + .bin, or hand-assembled .glb) with known
// contents, every kind of broken input, and the four shared scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "scene/errors.h"
#include "scene/gltf_loader.h"
#include "scene/lights.h"

namespace lll {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kUnsignedByte = 5121;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

// A 2x2 RGBA PNG: red, green / blue, white at alpha 128.
const std::vector<uint8_t> kPng2x2 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d,
    0x24, 0x00, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xf0,
    0x1f, 0x0c, 0x81, 0x34, 0x08, 0x34, 0x00, 0x00, 0x49, 0x49, 0x09, 0x78, 0x9c, 0x51, 0x17, 0x92,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
const std::vector<uint8_t> kPng2x2Rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};

void writeBytes(const fs::path& path, const void* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), std::streamsize(size));
  ASSERT_TRUE(out.good()) << path;
}

void writeText(const fs::path& path, const std::string& text) {
  writeBytes(path, text.data(), text.size());
}

// A glTF document and its one binary buffer, built side by side.
struct GltfBuilder {
  json doc = {{"asset", {{"version", "2.0"}}},
              {"bufferViews", json::array()},
              {"accessors", json::array()},
              {"meshes", json::array()},
              {"nodes", json::array()}};
  std::vector<uint8_t> bin;
  std::vector<size_t> accessorByteOffset;  // where each accessor's data starts in `bin`

  int addBufferView(const void* data, size_t size) {
    bin.resize((bin.size() + 3) / 4 * 4, 0);
    const size_t offset = bin.size();
    bin.resize(offset + size);
    std::memcpy(bin.data() + offset, data, size);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}});
    return int(doc["bufferViews"].size() - 1);
  }

  template <typename T>
  int addAccessor(const std::vector<T>& values, int componentType, const std::string& type,
                  bool normalized = false) {
    const size_t components = type == "SCALAR" ? 1 : size_t(type.back() - '0');
    const int view = addBufferView(values.data(), values.size() * sizeof(T));
    json accessor = {{"bufferView", view},
                     {"componentType", componentType},
                     {"count", values.size() / components},
                     {"type", type}};
    if (normalized) accessor["normalized"] = true;
    doc["accessors"].push_back(accessor);
    accessorByteOffset.push_back(doc["bufferViews"][view]["byteOffset"].get<size_t>());
    return int(doc["accessors"].size() - 1);
  }

  int addPositions(const std::vector<float>& xyz) { return addAccessor(xyz, kFloat, "VEC3"); }

  int addMesh(const json& primitives, const std::string& name = "") {
    json mesh = {{"primitives", primitives}};
    if (!name.empty()) mesh["name"] = name;
    doc["meshes"].push_back(mesh);
    return int(doc["meshes"].size() - 1);
  }

  int addNode(const json& node) {
    doc["nodes"].push_back(node);
    return int(doc["nodes"].size() - 1);
  }

  void setScene(const std::vector<int>& roots) {
    doc["scenes"] = json::array({{{"nodes", roots}}});
    doc["scene"] = 0;
  }

  // Writes <name>.gltf and <name>.bin into `dir`; returns the .gltf path.
  fs::path writeGltf(const fs::path& dir, const std::string& name) {
    doc["buffers"] = json::array({{{"uri", name + ".bin"}, {"byteLength", bin.size()}}});
    writeBytes(dir / (name + ".bin"), bin.data(), bin.size());
    writeText(dir / (name + ".gltf"), doc.dump(1));
    return dir / (name + ".gltf");
  }

  // Assembles <name>.glb by hand: 12-byte header, JSON chunk, BIN chunk, each 4-byte aligned.
  fs::path writeGlb(const fs::path& dir, const std::string& name) {
    std::vector<uint8_t> payload = bin;
    payload.resize((payload.size() + 3) / 4 * 4, 0);
    doc["buffers"] = json::array({{{"byteLength", bin.size()}}});
    std::string text = doc.dump();
    text.resize((text.size() + 3) / 4 * 4, ' ');
    std::vector<uint8_t> glb = {'g', 'l', 'T', 'F'};
    auto put32 = [&](uint32_t v) {
      for (int i = 0; i < 4; ++i) glb.push_back(uint8_t(v >> (8 * i)));
    };
    put32(2);
    put32(uint32_t(12 + 8 + text.size() + 8 + payload.size()));
    put32(uint32_t(text.size()));
    put32(0x4E4F534A);  // "JSON"
    glb.insert(glb.end(), text.begin(), text.end());
    put32(uint32_t(payload.size()));
    put32(0x004E4942);  // "BIN\0"
    glb.insert(glb.end(), payload.begin(), payload.end());
    writeBytes(dir / (name + ".glb"), glb.data(), glb.size());
    return dir / (name + ".glb");
  }
};

// A unit quad in z = 0 facing +z, with normals, UVs, 16-bit indices and material 0 "Painted".
GltfBuilder quadScene() {
  GltfBuilder b;
  const int position = b.addPositions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  const int normal = b.addAccessor<float>({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
  const int uv = b.addAccessor<float>({0, 0, 1, 0, 1, 1, 0, 1}, kFloat, "VEC2");
  const int indices = b.addAccessor<uint16_t>({0, 1, 2, 0, 2, 3}, kUnsignedShort, "SCALAR");
  b.addMesh(json::array({{{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                          {"indices", indices},
                          {"material", 0}}}),
            "quad");
  b.doc["materials"] = json::array({{{"name", "Painted"}}});
  b.setScene({b.addNode({{"mesh", 0}})});
  return b;
}

void expectVec3Near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expectMat4Near(const glm::mat4& actual, const glm::mat4& expected) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(actual[c][r], expected[c][r], 1e-5f) << "column " << c << " row " << r;
  }
}

bool anyWarningContains(const LoadReport& report, const std::string& a, const std::string& b = "") {
  for (const std::string& warning : report.warnings) {
    if (warning.find(a) != std::string::npos && warning.find(b) != std::string::npos) return true;
  }
  return false;
}

// Loading `path` must throw InputError naming the file (and `detail`, when given).
void expectInputError(const fs::path& path, const std::string& detail = "") {
  try {
    loadGltf(path);
    ADD_FAILURE() << "loading " << path << " did not throw";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << "expected '" << detail << "' in: " << message;
  }
}

class GltfLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = fs::temp_directory_path() / ("lll-gltf-" + test + "-" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  fs::path dir_;
};

TEST_F(GltfLoaderTest, LoadsQuadGeometry) {
  const Scene scene = loadGltf(quadScene().writeGltf(dir_, "quad"));
  EXPECT_EQ(scene.name, "quad");
  ASSERT_EQ(scene.vertices.size(), 4u);
  expectVec3Near(scene.vertices[2].position, {1, 1, 0});
  expectVec3Near(scene.vertices[3].position, {0, 1, 0});
  expectVec3Near(scene.vertices[1].normal, {0, 0, 1});
  EXPECT_EQ(scene.vertices[2].uv, glm::vec2(1, 1));
  EXPECT_EQ(scene.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].name, "quad");
  ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
  EXPECT_EQ(scene.meshes[0].primitives[0].indexCount, 6u);
  ASSERT_EQ(scene.instances.size(), 1u);
  expectMat4Near(scene.instances[0].transform, glm::mat4(1.0f));
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "Painted");
}

// TANGENT (xyz and the bitangent's handedness w) reaches the vertices; without it w is 0, which
// tells the shaders to build the frame from derivatives; a w that is not +-1 is an error.
TEST_F(GltfLoaderTest, TangentsAreReadAndChecked) {
  EXPECT_EQ(loadGltf(quadScene().writeGltf(dir_, "plain")).vertices[0].tangent, glm::vec4(0.0f));
  GltfBuilder b = quadScene();
  const int tangent =
      b.addAccessor<float>({1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, -1, 0, 1, 0, -1}, kFloat, "VEC4");
  b.doc["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = tangent;
  const Scene scene = loadGltf(b.writeGltf(dir_, "tangents"));
  ASSERT_EQ(scene.vertices.size(), 4u);
  EXPECT_EQ(scene.vertices[1].tangent, glm::vec4(1, 0, 0, 1));
  EXPECT_EQ(scene.vertices[3].tangent, glm::vec4(0, 1, 0, -1));
  const size_t w = b.accessorByteOffset[size_t(tangent)] + 3 * sizeof(float);
  const float half = 0.5f;
  std::memcpy(b.bin.data() + w, &half, sizeof(half));
  expectInputError(b.writeGltf(dir_, "bad-tangent"), "TANGENT 0");
}

TEST_F(GltfLoaderTest, SecondPrimitiveIndicesAreRelativeToItsFirstVertex) {
  GltfBuilder b = quadScene();
  const int position = b.addPositions({5, 0, 0, 6, 0, 0, 5, 1, 0});
  const int indices = b.addAccessor<uint32_t>({2, 1, 0}, kUnsignedInt, "SCALAR");
  b.doc["meshes"][0]["primitives"].push_back(
      {{"attributes", {{"POSITION", position}}}, {"indices", indices}});
  const Scene scene = loadGltf(b.writeGltf(dir_, "two"));
  ASSERT_EQ(scene.meshes[0].primitives.size(), 2u);
  const Primitive& second = scene.meshes[0].primitives[1];
  EXPECT_EQ(second.firstIndex, 6u);
  EXPECT_EQ(second.indexCount, 3u);
  EXPECT_EQ(second.vertexOffset, 4u);
  // No normals: flat shading gives the triangle its own three vertices, in triangle order.
  EXPECT_EQ(std::vector<uint32_t>(scene.indices.begin() + 6, scene.indices.end()),
            (std::vector<uint32_t>{0, 1, 2}));
  expectVec3Near(scene.vertices[second.vertexOffset].position, {5, 1, 0});
  expectVec3Near(scene.vertices[second.vertexOffset].normal, {0, 0, -1});  // (2,1,0) winds clockwise
  EXPECT_EQ(scene.vertices[second.vertexOffset].uv, glm::vec2(0, 0));      // no TEXCOORD_0
}

TEST_F(GltfLoaderTest, MaterialFactors) {
  GltfBuilder b = quadScene();
  b.doc["materials"][0] = {
      {"name", "Glow"},
      {"pbrMetallicRoughness",
       {{"baseColorFactor", {0.5, 0.25, 1.0, 0.75}}, {"metallicFactor", 0.2}, {"roughnessFactor", 0.7}}},
      {"emissiveFactor", {1.0, 0.5, 0.0}},
      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}},
      {"alphaMode", "MASK"},
      {"alphaCutoff", 0.3},
      {"doubleSided", true}};
  b.doc["materials"].push_back({{"alphaMode", "BLEND"}});
  b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  const Scene scene = loadGltf(b.writeGltf(dir_, "materials"));
  ASSERT_EQ(scene.materials.size(), 2u);
  const Material& glow = scene.materials[0];
  EXPECT_EQ(glow.name, "Glow");
  EXPECT_EQ(glow.baseColorFactor, glm::vec4(0.5f, 0.25f, 1.0f, 0.75f));
  EXPECT_FLOAT_EQ(glow.metallic, 0.2f);
  EXPECT_FLOAT_EQ(glow.roughness, 0.7f);
  EXPECT_EQ(glow.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f));
  EXPECT_FLOAT_EQ(glow.emissiveStrength, 4.0f);
  EXPECT_EQ(glow.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(glow.alphaCutoff, 0.3f);
  EXPECT_TRUE(glow.doubleSided);
  EXPECT_EQ(glow.baseColorTexture, -1);
  EXPECT_EQ(scene.materials[1].alphaMode, AlphaMode::Blend);
  EXPECT_FALSE(scene.materials[1].doubleSided);
  EXPECT_FLOAT_EQ(scene.materials[1].metallic, 1.0f);  // glTF default
}

TEST_F(GltfLoaderTest, PrimitivesWithoutMaterialShareOneDefaultMaterial) {
  GltfBuilder b = quadScene();
  b.doc["meshes"][0]["primitives"][0].erase("material");
  b.doc["meshes"][0]["primitives"].push_back(b.doc["meshes"][0]["primitives"][0]);
  const Scene scene = loadGltf(b.writeGltf(dir_, "nomaterial"));
  ASSERT_EQ(scene.materials.size(), 2u);  // "Painted", unused, then the default
  const auto& primitives = scene.meshes[0].primitives;
  ASSERT_EQ(primitives.size(), 2u);
  EXPECT_EQ(primitives[0].material, 1u);
  EXPECT_EQ(primitives[1].material, 1u);
  EXPECT_EQ(scene.materials[1].baseColorFactor, glm::vec4(1.0f));
  EXPECT_FLOAT_EQ(scene.materials[1].metallic, 1.0f);
  EXPECT_FLOAT_EQ(scene.materials[1].roughness, 1.0f);
}

TEST_F(GltfLoaderTest, NodeHierarchyGivesWorldTransforms) {
  GltfBuilder b = quadScene();
  b.doc["nodes"] =
      json::array({{{"translation", {1, 2, 3}}, {"children", {1, 2}}},
                   {{"scale", {2, 2, 2}}, {"mesh", 0}},
                   // column-major: translation (0, 0, 10) in the last column
                   {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 10, 1}}, {"children", {3}}},
                   {{"rotation", {0, 0, 0.7071068, 0.7071068}}, {"mesh", 0}}});
  const Scene scene = loadGltf(b.writeGltf(dir_, "hierarchy"));
  ASSERT_EQ(scene.instances.size(), 2u);
  const glm::mat4 parent = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  expectMat4Near(scene.instances[0].transform, glm::scale(parent, glm::vec3(2.0f)));
  expectVec3Near(glm::vec3(scene.instances[0].transform * glm::vec4(1, 1, 0, 1)), {3, 4, 3});
  // 90 degrees about z maps x to y, below a translation of (1, 2, 13).
  expectVec3Near(glm::vec3(scene.instances[1].transform * glm::vec4(1, 0, 0, 1)), {1, 3, 13});
}

TEST_F(GltfLoaderTest, UsesTheDefaultSceneOnly) {
  GltfBuilder b = quadScene();
  b.addNode({{"mesh", 0}, {"translation", {0, 7, 0}}});
  b.doc["scenes"] = json::array({{{"nodes", {0}}}, {{"nodes", {1}}}});
  b.doc["scene"] = 1;
  const Scene scene = loadGltf(b.writeGltf(dir_, "scenes"));
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_FLOAT_EQ(scene.instances[0].transform[3].y, 7.0f);
}

TEST_F(GltfLoaderTest, NoScenesMeansAllRootNodes) {
  GltfBuilder b = quadScene();
  b.doc.erase("scenes");
  b.doc.erase("scene");
  b.doc["nodes"] = json::array({{{"mesh", 0}, {"children", {2}}}, {{"mesh", 0}}, {{"mesh", 0}}});
  const Scene scene = loadGltf(b.writeGltf(dir_, "noscenes"));
  EXPECT_EQ(scene.instances.size(), 3u);
}

TEST_F(GltfLoaderTest, PunctualLights) {
  GltfBuilder b = quadScene();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  b.doc["extensions"]["KHR_lights_punctual"]["lights"] =
      json::array({{{"type", "point"}, {"color", {1.0, 0.5, 0.25}}, {"intensity", 10.0}, {"range", 5.0}},
                   {{"type", "spot"},
                    {"intensity", 20.0},
                    {"range", 8.0},
                    {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}},
                   {{"type", "point"}, {"intensity", 3.0}, {"color", {0.0, 1.0, 0.0}}},
                   {{"type", "directional"}},
                   {{"type", "spot"}, {"spot", json::object()}}});
  auto light = [](int index) { return json{{"KHR_lights_punctual", {{"light", index}}}}; };
  const float s = std::sqrt(0.5f);
  b.doc["nodes"] =
      json::array({{{"translation", {10, 0, 0}}, {"children", {1}}},
                   {{"translation", {1, 2, 3}}, {"extensions", light(0)}},
                   // -90 degrees about x: the spot's -z turns to -y
                   {{"translation", {0, 5, 0}}, {"rotation", {-s, 0, 0, s}}, {"extensions", light(1)}},
                   {{"extensions", light(2)}},
                   {{"extensions", light(3)}},
                   {{"extensions", light(4)}}});
  b.setScene({0, 2, 3, 4, 5});
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "lights"), &report);
  ASSERT_EQ(scene.lights.size(), 4u);

  const Light& point = scene.lights[0];
  EXPECT_EQ(point.type, LightType::Point);
  expectVec3Near(point.position, {11, 2, 3});
  EXPECT_EQ(point.color, glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(point.intensity, 10.0f);
  EXPECT_FLOAT_EQ(point.range, 5.0f);

  const Light& spot = scene.lights[1];
  EXPECT_EQ(spot.type, LightType::Spot);
  expectVec3Near(spot.position, {0, 5, 0});
  expectVec3Near(spot.direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(spot.range, 8.0f);
  EXPECT_FLOAT_EQ(spot.innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(spot.outerConeAngle, 0.6f);

  const Light& unbounded = scene.lights[2];
  EXPECT_FLOAT_EQ(unbounded.range, rangeForUnboundedLight(3.0f, glm::vec3(0, 1, 0)));

  const Light& defaultSpot = scene.lights[3];  // glTF defaults: intensity 1, cone 0 .. pi/4
  EXPECT_FLOAT_EQ(defaultSpot.innerConeAngle, 0.0f);
  EXPECT_FLOAT_EQ(defaultSpot.outerConeAngle, 0.7853982f);
  EXPECT_FLOAT_EQ(defaultSpot.range, rangeForUnboundedLight(1.0f, glm::vec3(1.0f)));
  EXPECT_TRUE(anyWarningContains(report, "directional"));
}

TEST_F(GltfLoaderTest, PerspectiveCameras) {
  GltfBuilder b = quadScene();
  b.doc["cameras"] = json::array(
      {{{"name", "Main"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}},
       {{"type", "perspective"}, {"perspective", {{"yfov", 1.2}, {"znear", 0.1}}}}});
  const float s = std::sqrt(0.5f);
  b.addNode({{"camera", 0}, {"translation", {0, 1, 5}}});
  // 90 degrees about y: looks along -x.
  b.addNode({{"camera", 1}, {"rotation", {0, s, 0, s}}});
  b.setScene({0, 1, 2});
  const Scene scene = loadGltf(b.writeGltf(dir_, "cameras"));
  ASSERT_EQ(scene.cameras.size(), 2u);
  EXPECT_EQ(scene.cameras[0].name, "Main");
  expectVec3Near(scene.cameras[0].eye, {0, 1, 5});
  expectVec3Near(scene.cameras[0].target, {0, 1, 4});
  expectVec3Near(scene.cameras[0].up, {0, 1, 0});
  EXPECT_FLOAT_EQ(scene.cameras[0].yfov, 0.8f);
  EXPECT_EQ(scene.cameras[1].name, "gltf-camera-1");
  expectVec3Near(scene.cameras[1].target, {-1, 0, 0});
  EXPECT_FLOAT_EQ(scene.cameras[1].yfov, 1.2f);
}

TEST_F(GltfLoaderTest, IndexTypesAndNormalizedTexcoords) {
  GltfBuilder b;
  const int position = b.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0});
  const int normal = b.addAccessor<float>({0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
  const int uvByte = b.addAccessor<uint8_t>({255, 0, 0, 255, 51, 102}, kUnsignedByte, "VEC2", true);
  const int uvShort = b.addAccessor<uint16_t>({65535, 0, 0, 65535, 0, 0}, kUnsignedShort, "VEC2", true);
  const int bytes = b.addAccessor<uint8_t>({2, 1, 0}, kUnsignedByte, "SCALAR");
  const int words = b.addAccessor<uint32_t>({1, 2, 0}, kUnsignedInt, "SCALAR");
  const json attributes = {{"POSITION", position}, {"NORMAL", normal}};
  json withByteUv = attributes;
  withByteUv["TEXCOORD_0"] = uvByte;
  json withShortUv = attributes;
  withShortUv["TEXCOORD_0"] = uvShort;
  b.addMesh(json::array({{{"attributes", withByteUv}, {"indices", bytes}},
                         {{"attributes", withShortUv}, {"indices", words}},
                         {{"attributes", attributes}}}));
  b.setScene({b.addNode({{"mesh", 0}})});
  const Scene scene = loadGltf(b.writeGltf(dir_, "types"));
  EXPECT_EQ(scene.indices, (std::vector<uint32_t>{2, 1, 0, 1, 2, 0, 0, 1, 2}));
  ASSERT_EQ(scene.vertices.size(), 9u);
  EXPECT_NEAR(scene.vertices[0].uv.x, 1.0f, 1e-6f);
  EXPECT_NEAR(scene.vertices[2].uv.x, 0.2f, 1e-6f);
  EXPECT_NEAR(scene.vertices[2].uv.y, 0.4f, 1e-6f);
  EXPECT_NEAR(scene.vertices[4].uv.y, 1.0f, 1e-6f);
}

TEST_F(GltfLoaderTest, StripsAndFansBecomeListsAndLinesAreSkipped) {
  GltfBuilder b;
  const int position = b.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  const int normal = b.addAccessor<float>({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, kFloat, "VEC3");
  const json attributes = {{"POSITION", position}, {"NORMAL", normal}};
  b.addMesh(json::array({{{"attributes", attributes}, {"mode", 5}},
                         {{"attributes", attributes}, {"mode", 6}},
                         {{"attributes", attributes}, {"mode", 1}},
                         {{"attributes", attributes}, {"mode", 0}}}));
  b.setScene({b.addNode({{"mesh", 0}})});
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "modes"), &report);
  ASSERT_EQ(scene.meshes[0].primitives.size(), 2u);
  EXPECT_EQ(scene.indices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3, 1, 2, 0, 2, 3, 0}));
  EXPECT_TRUE(anyWarningContains(report, "primitive 2", "lines"));
  EXPECT_TRUE(anyWarningContains(report, "primitive 3", "points"));
}

TEST_F(GltfLoaderTest, TexturesAreDecodedPerColourSpace) {
  GltfBuilder b = quadScene();
  writeBytes(dir_ / "checker.png", kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}},
                                                   {"metallicRoughnessTexture", {{"index", 0}}}};
  b.doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
  b.doc["materials"][0]["normalTexture"] = {{"index", 0}, {"scale", 0.5}};
  b.doc["materials"][0]["occlusionTexture"] = {{"index", 0}, {"strength", 0.25}};
  const Scene scene = loadGltf(b.writeGltf(dir_, "textured"));
  ASSERT_EQ(scene.textures.size(), 2u);  // one image used as sRGB colour and as linear data
  const Material& m = scene.materials[0];
  ASSERT_GE(m.baseColorTexture, 0);
  ASSERT_GE(m.metallicRoughnessTexture, 0);
  EXPECT_EQ(m.emissiveTexture, m.baseColorTexture);
  EXPECT_EQ(m.normalTexture, m.metallicRoughnessTexture);
  EXPECT_EQ(m.occlusionTexture, m.metallicRoughnessTexture);
  EXPECT_NE(m.baseColorTexture, m.metallicRoughnessTexture);
  EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
  EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
  const Texture& colour = scene.textures[size_t(m.baseColorTexture)];
  EXPECT_TRUE(colour.srgb);
  EXPECT_FALSE(scene.textures[size_t(m.metallicRoughnessTexture)].srgb);
  EXPECT_EQ(colour.width, 2u);
  EXPECT_EQ(colour.height, 2u);
  EXPECT_EQ(colour.rgba, kPng2x2Rgba);
}

TEST_F(GltfLoaderTest, MissingOrUndecodableImageWarnsAndLeavesNoTexture) {
  GltfBuilder b = quadScene();
  writeText(dir_ / "garbage.png", "this is not an image at all");
  b.doc["images"] = json::array({{{"uri", "missing.png"}}, {{"uri", "garbage.png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
  b.doc["materials"][0]["normalTexture"] = {{"index", 1}};
  LoadReport report;
  const Scene scene = loadGltf(b.writeGltf(dir_, "missingtexture"), &report);
  EXPECT_EQ(scene.materials[0].baseColorTexture, -1);
  EXPECT_EQ(scene.materials[0].normalTexture, -1);
  EXPECT_TRUE(scene.textures.empty());
  EXPECT_TRUE(anyWarningContains(report, "missing.png", "Painted"));
  EXPECT_TRUE(anyWarningContains(report, "garbage.png", "Painted"));
  EXPECT_EQ(scene.vertices.size(), 4u);  // the rest of the file still loads
}

TEST_F(GltfLoaderTest, GlbMatchesGltfAndDecodesBufferViewImages) {
  GltfBuilder b = quadScene();
  const int view = b.addBufferView(kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"bufferView", view}, {"mimeType", "image/png"}}});
  b.doc["textures"] = json::array({{{"source", 0}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}},
                                                   {"baseColorFactor", {0.1, 0.2, 0.3, 1.0}}};
  const Scene fromGlb = loadGltf(b.writeGlb(dir_, "binary"));
  GltfBuilder text = quadScene();
  const Scene fromGltf = loadGltf(text.writeGltf(dir_, "text"));
  EXPECT_EQ(fromGlb.name, "binary");
  ASSERT_EQ(fromGlb.vertices.size(), fromGltf.vertices.size());
  for (size_t i = 0; i < fromGlb.vertices.size(); ++i) {
    EXPECT_EQ(fromGlb.vertices[i].position, fromGltf.vertices[i].position);
    EXPECT_EQ(fromGlb.vertices[i].normal, fromGltf.vertices[i].normal);
    EXPECT_EQ(fromGlb.vertices[i].uv, fromGltf.vertices[i].uv);
  }
  EXPECT_EQ(fromGlb.indices, fromGltf.indices);
  EXPECT_EQ(fromGlb.materials[0].baseColorFactor, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
  ASSERT_EQ(fromGlb.materials[0].baseColorTexture, 0);
  EXPECT_EQ(fromGlb.textures[0].rgba, kPng2x2Rgba);
}

// Bad input: each case must throw InputError whose message names the file.

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
  b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  expectInputError(b.writeGltf(dir_, "draco"), "KHR_draco_mesh_compression");
}

TEST_F(GltfLoaderTest, SupportedRequiredExtensionsLoad) {
  GltfBuilder b = quadScene();
  b.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_texture_transform"};
  b.doc["extensionsRequired"] = {"KHR_lights_punctual", "KHR_texture_transform"};
  LoadReport report;
  EXPECT_EQ(loadGltf(b.writeGltf(dir_, "required"), &report).vertices.size(), 4u);
  EXPECT_TRUE(anyWarningContains(report, "KHR_texture_transform"));
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

// The shared CC-BY scenes load whole and consistent.
struct AssetScene {
  const char* name;
  uint64_t triangles;  // from assets/README.md
};

class GltfAssetsTest : public ::testing::TestWithParam<AssetScene> {};

TEST_P(GltfAssetsTest, LoadsConsistently) {
  const std::string name = GetParam().name;
  const fs::path path = fs::path(LLL_ASSETS_DIR) / name / (name + ".gltf");
  LoadReport report;
  const Scene scene = loadGltf(path, &report);
  for (const std::string& warning : report.warnings) ADD_FAILURE() << "unexpected warning: " << warning;
  EXPECT_EQ(scene.name, name);
  ASSERT_FALSE(scene.vertices.empty());
  ASSERT_FALSE(scene.instances.empty());
  for (const Vertex& v : scene.vertices) {
    ASSERT_TRUE(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
  }
  for (const Mesh& mesh : scene.meshes) {
    for (const Primitive& p : mesh.primitives) {
      ASSERT_LE(uint64_t(p.firstIndex) + p.indexCount, scene.indices.size()) << mesh.name;
      ASSERT_LT(p.material, scene.materials.size()) << mesh.name;
      for (uint32_t i = p.firstIndex; i < p.firstIndex + p.indexCount; ++i) {
        ASSERT_LT(uint64_t(scene.indices[i]) + p.vertexOffset, scene.vertices.size()) << mesh.name;
      }
    }
  }
  uint64_t triangles = 0;
  for (const Instance& instance : scene.instances) {
    ASSERT_LT(instance.mesh, scene.meshes.size());
    for (const Primitive& p : scene.meshes[instance.mesh].primitives) triangles += p.indexCount / 3;
  }
  EXPECT_EQ(triangles, GetParam().triangles);
  std::ifstream file(path);
  EXPECT_EQ(scene.materials.size(), json::parse(file)["materials"].size());
}

INSTANTIATE_TEST_SUITE_P(GltfSharedScenes, GltfAssetsTest,
                         ::testing::Values(AssetScene{"camp", 6285}, AssetScene{"cave", 5894},
                                           AssetScene{"garage", 11358}, AssetScene{"space", 15861}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(GltfAssets, CaveHasABlendedMaterial) {
  const Scene scene = loadGltf(LLL_ASSETS_DIR "/cave/cave.gltf");
  EXPECT_TRUE(std::any_of(scene.materials.begin(), scene.materials.end(),
                          [](const Material& m) { return m.alphaMode == AlphaMode::Blend; }));
}

TEST(GltfAssets, CampHasItsCamera) {
  const Scene scene = loadGltf(LLL_ASSETS_DIR "/camp/camp.gltf");
  ASSERT_EQ(scene.cameras.size(), 1u);
  EXPECT_EQ(scene.cameras[0].name, "Camera.001");
  EXPECT_NEAR(scene.cameras[0].yfov, 0.50338f, 1e-4f);
  EXPECT_NEAR(glm::length(scene.cameras[0].target - scene.cameras[0].eye), 1.0f, 1e-4f);
}

}  // namespace
}  // namespace lll
