#pragma once
// Shared by the glTF loader tests (test_gltf_loader.cpp: files with known contents and the shared
// scenes; test_gltf_broken_input.cpp: every kind of broken input): small glTF files written per test
// (JSON + .bin, or hand-assembled .glb), and the checks they use.
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

#include "core/errors.h"
#include "scene/gltf_loader.h"
#include "scene/lights.h"

namespace lll::gltf_test {

namespace fs = std::filesystem;
using nlohmann::json;

inline constexpr int kUnsignedByte = 5121;
inline constexpr int kUnsignedShort = 5123;
inline constexpr int kUnsignedInt = 5125;
inline constexpr int kFloat = 5126;

// A 2x2 RGBA PNG: red, green / blue, white at alpha 128.
inline const std::vector<uint8_t> kPng2x2 = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x06, 0x00, 0x00, 0x00, 0x72, 0xb6, 0x0d,
    0x24, 0x00, 0x00, 0x00, 0x13, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xf0,
    0x1f, 0x0c, 0x81, 0x34, 0x08, 0x34, 0x00, 0x00, 0x49, 0x49, 0x09, 0x78, 0x9c, 0x51, 0x17, 0x92,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};
// A 2 x 2 lossless WebP (EXT_texture_webp) of red, green at half alpha, blue and clear white.
inline const std::vector<uint8_t> kWebp2x2 = {
    82,  73,  70,  70,  48, 0,  0,  0,   87,  69, 66,  80,  86,  80,  56,  76,  35,  0, 0,
    0,   47,  1,   64,  0,  16, 31, 48,  255, 2,  130, 34,  255, 71,  219, 127, 129, 0, 193,
    185, 115, 193, 141, 42, 65, 77, 219, 6,   44, 126, 147, 142, 136, 254, 199, 1,   0};
inline const std::vector<uint8_t> kWebp2x2Rgba = {255, 0, 0,   255, 0,   255, 0,   128,
                                                  0,   0, 255, 255, 255, 255, 255, 0};
inline const std::vector<uint8_t> kPng2x2Rgba = {255, 0, 0,   255, 0,   255, 0,   255,
                                                 0,   0, 255, 255, 255, 255, 255, 128};

inline void writeBytes(const fs::path& path, const void* data, size_t size) {
  std::ofstream out(path, std::ios::binary);
  out.write(static_cast<const char*>(data), std::streamsize(size));
  ASSERT_TRUE(out.good()) << path;
}

inline void writeText(const fs::path& path, const std::string& text) {
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
    const size_t side = type == "SCALAR" ? 1 : size_t(type.back() - '0');
    const size_t components = type.rfind("MAT", 0) == 0 ? side * side : side;
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
inline GltfBuilder quadScene() {
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

inline void expectVec3Near(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

inline void expectMat4Near(const glm::mat4& actual, const glm::mat4& expected) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(actual[c][r], expected[c][r], 1e-5f) << "column " << c << " row " << r;
  }
}

inline bool anyWarningContains(const LoadReport& report, const std::string& a, const std::string& b = "") {
  for (const std::string& warning : report.warnings) {
    if (warning.find(a) != std::string::npos && warning.find(b) != std::string::npos) return true;
  }
  return false;
}

// Loading `path` must throw InputError naming the file (and `detail`, when given).
inline void expectInputError(const fs::path& path, const std::string& detail = "",
                             const GltfLimits& limits = {}) {
  try {
    loadGltf(path, nullptr, limits);
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

}  // namespace lll::gltf_test
