// Broken glTF files that once rendered NaN or black with exit 0 (issue 16): each now ends in exit
// code 2 naming the file, the field and the value, or, where glTF allows a repair, in a warning and
// an image that is finite and not black.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "cli_test_support.h"
#include "render/image_io.h"

namespace lll {
namespace {

using namespace lll::test;

// The quad, plus unit normals (accessor 2, bufferView 2, at byte 60 of the .bin), a light above
// it and a camera looking down at it.
struct LitQuad : QuadGltf {
  LitQuad() {
    const float normals[] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    const size_t at = bin.size();
    bin.resize(at + sizeof(normals));
    std::memcpy(bin.data() + at, normals, sizeof(normals));
    doc["buffers"][0]["byteLength"] = bin.size();
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", sizeof(normals)}});
    doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = {
        {{"type", "point"}, {"color", {1, 1, 1}}, {"intensity", 5.0}, {"range", 10.0}}};
    doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.01}}}}};
    // Node 0 the quad; node 1 the light, 1 m above it; node 2 the camera, 3 m up looking down.
    doc["nodes"].push_back(
        {{"translation", {0, 1, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    doc["nodes"].push_back(
        {{"camera", 0}, {"translation", {0, 3, 0}}, {"rotation", {-0.7071068, 0, 0, 0.7071068}}});
    doc["scenes"][0]["nodes"] = {0, 1, 2};
  }
  void setFloats(size_t byte, std::initializer_list<float> values) {
    for (float v : values) {
      std::memcpy(bin.data() + byte, &v, 4);
      byte += 4;
    }
  }
};

struct PfmImage {
  uint32_t width = 0, height = 0;
  std::vector<float> rgb;
};

PfmImage readPfm(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  PfmImage image;
  std::string magic;
  float scale = 0.0f;
  in >> magic >> image.width >> image.height >> scale;
  in.get();
  image.rgb.resize(size_t(image.width) * image.height * 3);
  in.read(reinterpret_cast<char*>(image.rgb.data()), std::streamsize(image.rgb.size() * 4));
  return image;
}

class HostileGltf : public CliTest {
 protected:
  // Renders `quad` written as broken.gltf; the HDR image goes to out.pfm.
  CliResult renderQuad(const LitQuad& quad) {
    path_ = quad.write(dir_, "broken").string();
    return runLll({"render", path_, "--width", "32", "--height", "18", "--out", outPng(), "--hdr",
                   (dir_ / "out.pfm").string()});
  }
  // Exit 2 naming the file and each of `named`, nothing written.
  void expectRejected(const LitQuad& quad, const std::vector<std::string>& named) {
    const CliResult r = renderQuad(quad);
    std::vector<std::string> all = {path_};
    all.insert(all.end(), named.begin(), named.end());
    expectBadInput(r, all);
    EXPECT_FALSE(fs::exists(dir_ / "out.pfm"));
  }
  // Exit 0 with a warning naming each of `warned`, and an HDR image with no NaN and some light.
  void expectRepaired(const LitQuad& quad, const std::vector<std::string>& warned) {
    const CliResult r = renderQuad(quad);
    ASSERT_EQ(r.exitCode, 0) << r;
    for (const std::string& w : warned) EXPECT_TRUE(contains(r.output, w)) << "'" << w << "' not said: " << r;
    EXPECT_EQ(contains(r.output, "warning"), !warned.empty()) << r;
    const PfmImage image = readPfm(dir_ / "out.pfm");
    ASSERT_EQ(image.rgb.size(), 32u * 18u * 3u);
    float brightest = 0.0f;
    for (float v : image.rgb) {
      ASSERT_FALSE(std::isnan(v)) << r;
      brightest = std::max(brightest, v);
    }
    EXPECT_GT(brightest, 0.05f) << "black image: " << r;
  }
  std::string path_;
};

TEST_F(HostileGltf, TheLitQuadItselfRendersLit) {
  expectRepaired(LitQuad(), {});
}

TEST_F(HostileGltf, NormalAccessorWithoutBufferViewGetsFlatNormals) {
  LitQuad quad;
  quad.doc["accessors"][2].erase("bufferView");
  expectRepaired(quad, {"NORMAL", "zero length", "flat normals"});
}

TEST_F(HostileGltf, NanNormal) {
  LitQuad quad;
  quad.setFloats(60 + 12, {std::numeric_limits<float>::quiet_NaN()});
  expectRejected(quad, {"NORMAL", "nan"});
}

TEST_F(HostileGltf, NanTexcoord) {
  LitQuad quad;
  quad.doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
  quad.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 3;
  quad.doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");  // it shares the bytes
  quad.setFloats(60, {std::numeric_limits<float>::infinity()});
  expectRejected(quad, {"TEXCOORD_0", "inf"});
}

TEST_F(HostileGltf, BufferViewOffsetMisalignsItsAccessor) {
  LitQuad quad;
  quad.doc["bufferViews"][1]["byteOffset"] = 49;  // 16-bit indices at an odd byte
  expectRejected(quad, {"indices", "49", "not a multiple of its 2-byte components"});
}

TEST_F(HostileGltf, AccessorOffsetMisalignsItsFloats) {
  LitQuad quad;
  quad.doc["bufferViews"][2]["byteLength"] = 48 - 2;
  quad.doc["bufferViews"][2]["byteOffset"] = 62;
  quad.doc["accessors"][2]["count"] = 3;
  expectRejected(quad, {"NORMAL", "62", "not a multiple of its 4-byte components"});
}

TEST_F(HostileGltf, NumbersInfiniteAsFloats) {
  const std::vector<std::pair<std::function<void(json&)>, std::vector<std::string>>> cases = {
      {[](json& d) {
         d["materials"] = {
             {{"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e308}}}}}}};
         d["meshes"][0]["primitives"][0]["material"] = 0;
       },
       {"emissiveStrength", "1e+308"}},
      {[](json& d) {
         d["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1e308, 1, 1, 1}}}}}};
         d["meshes"][0]["primitives"][0]["material"] = 0;
       },
       {"baseColorFactor[0]", "1e+308"}},
      {[](json& d) { d["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1e308; },
       {"intensity", "1e+308"}},
      {[](json& d) {
         d["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {1e308, 1, 1};
       },
       {"color[0]", "1e+308"}},
      {[](json& d) { d["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1e30; },
       {"intensity", "above"}},
      {[](json& d) {
         d["nodes"][0]["scale"] = {1e39, 1, 1};
       },
       {"node 0 scale[0]", "1e+39"}},
      {[](json& d) {
         d["nodes"][0]["translation"] = {3e38, 0, 0};
         d["nodes"][0]["scale"] = {10, 1, 1};
       },
       {"node 0", "beyond the"}},
      {[](json& d) { d["cameras"][0]["perspective"]["yfov"] = 1e-300; },
       {"yfov", "1e-300", "0 as a 32-bit float"}},
  };
  for (const auto& [bend, named] : cases) {
    LitQuad quad;
    bend(quad.doc);
    expectRejected(quad, named);
  }
}

TEST_F(HostileGltf, MeshWithNoPrimitives) {
  LitQuad quad;
  quad.doc["meshes"].push_back({{"primitives", json::array()}});
  expectRejected(quad, {"mesh 'mesh 1'", "no primitives"});
}

TEST_F(HostileGltf, WronglyTypedFieldsAreNotAbsent) {
  const std::vector<std::pair<std::function<void(json&)>, std::vector<std::string>>> cases = {
      {[](json& d) { d["nodes"][0]["rotation"] = "NaN"; },
       {"nodes[0].rotation", "array of numbers", "\"NaN\""}},
      {[](json& d) { d["accessors"][0]["bufferView"] = "Infinity"; },
       {"accessors[0].bufferView", "an integer", "\"Infinity\""}},
      {[](json& d) {
         d["nodes"][0]["scale"] = {1, "2", 1};
       },
       {"nodes[0].scale", "array of numbers"}},
      {[](json& d) { d["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2.5; },
       {"meshes[0].primitives[0].attributes", "integers"}},
      {[](json& d) { d["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = "bright"; },
       {"extensions.KHR_lights_punctual.lights[0].intensity", "a number"}},
      {[](json& d) { d["cameras"][0]["perspective"]["yfov"] = json::array({0.9}); },
       {"cameras[0].perspective.yfov", "a number"}},
  };
  for (const auto& [bend, named] : cases) {
    LitQuad quad;
    bend(quad.doc);
    expectRejected(quad, named);
  }
}

TEST_F(HostileGltf, ZeroLengthRotation) {
  LitQuad quad;
  quad.doc["nodes"][0]["rotation"] = {0, 0, 0, 0};
  expectRejected(quad, {"node 0", "rotation of zero length"});
}

TEST_F(HostileGltf, NothingToDraw) {
  LitQuad quad;
  quad.doc["scenes"][0]["nodes"] = {1, 2};  // the light and the camera, no mesh
  expectRejected(quad, {"nothing to draw"});
}

TEST_F(HostileGltf, FactorsOutsideTheirRangeAreClamped) {
  LitQuad quad;
  quad.doc["materials"] = {{{"pbrMetallicRoughness", {{"roughnessFactor", 1.5}, {"metallicFactor", -0.25}}}}};
  quad.doc["meshes"][0]["primitives"][0]["material"] = 0;
  expectRepaired(quad, {"roughnessFactor is 1.5", "metallicFactor is -0.25", "clamped"});
}

// The brightest light allowed, 1 cm above the quad: shading overflows the half-float target there,
// and the tonemap must turn that into white, not NaN.
TEST_F(HostileGltf, BrightestLightAllowedGivesNoNan) {
  LitQuad quad;
  quad.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1e20;
  quad.doc["nodes"][1]["translation"] = {0, 0.01, 0};
  expectRepaired(quad, {});
  const LdrImage png = readPng(outPng());
  const uint8_t* centre = &png.rgba[(size_t(9) * png.width + 16) * 4];
  EXPECT_EQ(centre[0], 255);
  EXPECT_EQ(centre[1], 255);
}

}  // namespace
}  // namespace lll
