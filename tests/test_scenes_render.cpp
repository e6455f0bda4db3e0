// Every technique on every scene a user is likely to render first: the default atrium, the other
// built-in scenes and the four glTF scenes in assets/ (with 64 random lights, since they bring
// none) render under validation with no message, no NaN or infinity, and a picture that is not
// black; and a second frame of the same Renderer gives the first frame's image (stale stencil,
// link pools or accumulation targets would show there).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cctype>
#include <iostream>
#include <map>
#include <string>

#include "core/errors.h"
#include "gltf_test_support.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

struct SceneCase {
  std::string name;
  bool asset;  // a glTF file in assets/, else a built-in scene
};

void PrintTo(const SceneCase& c, std::ostream* os) {
  *os << c.name;
}

const Scene& sceneFor(const SceneCase& c) {
  static std::map<std::string, Scene> cache;
  auto it = cache.find(c.name);
  if (it != cache.end()) return it->second;
  SceneRequest request;
  request.scene = c.asset ? std::string(LLL_ASSETS_DIR) + "/" + c.name + "/" + c.name + ".gltf" : c.name;
  request.extraLights = c.asset ? 64 : 0;
  std::vector<std::string> warnings;
  Scene scene = loadScene(request, &warnings);
  for (const std::string& w : warnings) ADD_FAILURE() << "loader warning: " << w;
  return cache.emplace(c.name, std::move(scene)).first->second;
}

// The techniques as users pick them, on surfaces from the visibility buffer (the default) and from
// the geometry; lll also with the chapter's fragment shading, which walks the lists from a
// different stage.
struct TechniqueCase {
  const char* name;
  const char* technique;
  LllShade lllShade;
  SurfaceSource surfaces;
};
constexpr TechniqueCase kTechniques[] = {
    {"forward", "forward", LllShade::Compute, SurfaceSource::Visibility},
    {"forward_gbuffer", "forward", LllShade::Compute, SurfaceSource::Gbuffer},
    {"lll", "lll", LllShade::Compute, SurfaceSource::Visibility},
    {"lll_gbuffer", "lll", LllShade::Compute, SurfaceSource::Gbuffer},
    {"lll_fragment", "lll", LllShade::Fragment, SurfaceSource::Visibility},
    {"deferred", "deferred", LllShade::Compute, SurfaceSource::Visibility},
    {"prepass", "prepass", LllShade::Compute, SurfaceSource::Visibility},
    {"tiled", "tiled", LllShade::Compute, SurfaceSource::Visibility},
    {"clustered", "clustered", LllShade::Compute, SurfaceSource::Visibility},
    {"clustered_gbuffer", "clustered", LllShade::Compute, SurfaceSource::Gbuffer}};

void PrintTo(const TechniqueCase& t, std::ostream* os) {
  *os << t.name;
}

RenderSettings settingsFor(const TechniqueCase& t) {
  RenderSettings settings;
  settings.width = 96;
  settings.height = 54;
  settings.technique = t.technique;
  settings.lllShade = t.lllShade;
  settings.surfaces = t.surfaces;
  return settings;
}

using Case = std::tuple<TechniqueCase, SceneCase>;
class EveryTechniqueEveryScene : public ::testing::TestWithParam<Case> {};

TEST_P(EveryTechniqueEveryScene, FiniteAndNotBlack) {
  const auto& [t, c] = GetParam();
  const Scene& scene = sceneFor(c);
  ASSERT_FALSE(scene.lights.empty());
  const test::Rendered out = test::render(scene, settingsFor(t));
  ASSERT_EQ(out.hdr.width, 96u);
  ASSERT_EQ(out.hdr.height, 54u);
  ASSERT_EQ(out.hdr.rgba.size(), size_t(96) * 54 * 4);
  const test::HdrSummary hdr = test::summarize(out.hdr);
  EXPECT_EQ(hdr.nonFinite, 0u) << "pixels with NaN or infinity";
  // The dimmest scene, the cave (a small lit island in the dark), has a mean of about 0.002.
  EXPECT_GT(hdr.meanLuminance, 5e-4) << "the picture is (nearly) black";
  const double lit = test::shareAboveBlack(out.ldr);
  EXPECT_GE(lit, 0.10) << "too few pixels above black";  // space, mostly sky, has about 15%
  std::cout << t.name << " " << c.name << ": mean luminance " << hdr.meanLuminance << ", " << lit * 100.0
            << "% above black\n";
}

TEST_P(EveryTechniqueEveryScene, SecondFrameGivesTheFirstFramesImage) {
  const auto& [t, c] = GetParam();
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  Renderer renderer(context, sceneFor(c), settingsFor(t));
  renderer.renderFrame(true);
  const LdrImage first = renderer.ldrImage();
  renderer.renderFrame(true);
  const LdrImage second = renderer.ldrImage();
  // Not bit-exact: on a GPU the lists' order, and so the order lights are summed in, comes from
  // atomics and changes between frames. Anything left over from frame 1 moves pixels far more.
  test::expectWithinBound(second, first, test::ImageBound{50.0, 1, 0.999, 2},
                          std::string("frame 2 vs 1 ") + t.name + " " + c.name);
  const auto messages = context.validationMessages();
  for (size_t i = before; i < messages.size(); ++i) ADD_FAILURE() << messages[i];
}

// The cave through gltfpack (assets/cave-quantized: KHR_mesh_quantization, 16-bit positions and
// 8-bit normals) renders as the cave does, with the same 64 lights (scattered in the original's
// bounds) and camera: only the quantization of its vertices differs, which moves silhouettes by
// up to a pixel (one of the 14,400 pixels, on a crystal's edge against the dark, by 112 of 255).
TEST(QuantizedAssets, GltfpackCaveRendersAsTheCave) {
  Scene cave = loadScene(SceneRequest{std::string(LLL_ASSETS_DIR) + "/cave/cave.gltf", 64, 3});
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.camera = fmt::format("{},{},{},{},{},{}", -1.5, 1.2, 1.5, 0.0, 0.4, -0.8);
  // And compressed (EXT_meshopt_compression, gltfpack -cc -vpf: float positions, octahedral normals;
  // KHR_draco_mesh_compression, draco_transcoder with Blender's 14-bit positions, 10-bit normals;
  // EXT_mesh_gpu_instancing, gltfpack -mi -cc: the repeated meshes as instances of one node each).
  for (const char* file : {"cave-quantized/cave.gltf", "cave-meshopt/cave.glb", "cave-draco/cave.glb",
                           "cave-instanced/cave.glb"}) {
    Scene packed = loadScene(SceneRequest{std::string(LLL_ASSETS_DIR) + "/" + file});
    packed.lights = cave.lights;
    for (const char* technique : {"forward", "lll"}) {
      settings.technique = technique;
      const test::Rendered a = test::render(packed, settings), b = test::render(cave, settings);
      test::expectWithinBound(a.ldr, b.ldr, test::ImageBound{45.0, 4, 0.999, 255},
                              fmt::format("{} vs cave, {}", file, technique));
      EXPECT_GT(test::shareAboveBlack(b.ldr), 0.2) << technique;
    }
  }
}

// The visibility buffer's surface rebuild reads the scene's vertices as one storage buffer: where
// the device's largest (maxStorageBufferRange; lavapipe 128 MiB, 2,097,152 vertices of 64 bytes)
// holds fewer, the renderer refuses with the counts and the way out, --surfaces gbuffer, which
// then renders the scene. A GPU's 4 GiB would need a scene of 67 million vertices: checked there
// only as the limit.
TEST(DeviceLimits, SurfaceRebuildRefusesMoreVerticesThanAStorageBufferHolds) {
  Context& context = test::gpuContext();
  const uint64_t fit = context.properties().limits.maxStorageBufferRange / sizeof(Vertex);
  if (fit > (uint64_t(1) << 24)) {
    EXPECT_GE(uint64_t(context.properties().limits.maxStorageBufferRange), uint64_t(sizeof(Vertex)) << 24);
    return;
  }
  Scene scene = loadScene(SceneRequest{"plane", 0, 1});
  const uint32_t offset = uint32_t(scene.vertices.size());
  scene.vertices.resize(fit + 1);  // unused vertices past the plane's, then one triangle of them
  for (uint32_t i = 0; i < 3; ++i) {
    scene.vertices[offset + i].position = glm::vec3(float(i == 1), 0.5f + float(i == 2), 0.0f);
    scene.vertices[offset + i].normal = glm::vec3(0, 0, 1);
  }
  Mesh triangle;
  triangle.name = "triangle";
  triangle.primitives.push_back({uint32_t(scene.indices.size()), 3, offset, 0});
  scene.indices.insert(scene.indices.end(), {0, 1, 2});
  scene.meshes.push_back(triangle);
  scene.instances.push_back({uint32_t(scene.meshes.size() - 1), glm::mat4(1.0f)});
  RenderSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.technique = "lll";
  const std::string message = test::refusalOf(scene, settings);
  EXPECT_NE(message.find(std::to_string(fit + 1) + " vertices"), std::string::npos) << message;
  EXPECT_NE(message.find("--surfaces gbuffer"), std::string::npos) << message;
  settings.surfaces = SurfaceSource::Gbuffer;
  EXPECT_GT(test::shareAboveBlack(test::render(scene, settings).ldr), 0.1);
}

// A glTF whose material has data textures (normal, metallic-roughness, occlusion: 8-bit UNORM) as
// well as a colour one renders through the visibility buffer as through the geometry passes. On
// lavapipe (Mesa 22.3) the surface rebuild's textureLod of such a texture through the texture
// table crashed the process (LLVM segfault) before those textures were made 16-bit on CPU devices
// (render/gpu_scene.cpp); the shared assets have no textures, and the built-in scenes only colour.
TEST(TexturedAssets, DataTexturesRenderThroughTheVisibilityBuffer) {
  using namespace gltf_test;
  const fs::path dir =
      fs::temp_directory_path() / ("lll-data-textures-" + std::to_string(std::random_device{}()));
  fs::create_directories(dir);
  GltfBuilder b = quadScene();
  writeBytes(dir / "checker.png", kPng2x2.data(), kPng2x2.size());
  b.doc["images"] = json::array({{{"uri", "checker.png"}}});
  b.doc["samplers"] = json::array({json::object()});
  b.doc["textures"] = json::array({{{"source", 0}, {"sampler", 0}}});
  b.doc["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}},
                                                   {"metallicRoughnessTexture", {{"index", 0}}}};
  b.doc["materials"][0]["normalTexture"] = {{"index", 0}};
  b.doc["materials"][0]["occlusionTexture"] = {{"index", 0}};
  Scene scene = loadGltf(b.writeGltf(dir, "textured"));
  fs::remove_all(dir);
  Light light;
  light.position = glm::vec3(0.5f, 0.6f, 1.2f);
  light.intensity = 3.0f;
  light.range = 5.0f;
  scene.lights.push_back(light);
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.camera = "0.5,0.5,0.85,0.5,0.5,0";  // the quad fills the view
  for (const char* technique : {"forward", "lll", "deferred"}) {
    settings.technique = technique;
    settings.surfaces = SurfaceSource::Visibility;
    const test::Rendered visibility = test::render(scene, settings);
    settings.surfaces = SurfaceSource::Gbuffer;
    const test::Rendered gbuffer = test::render(scene, settings);
    test::expectWithinBound(visibility.ldr, gbuffer.ldr, test::kSameImage,
                            std::string("data textures, visibility vs gbuffer, ") + technique);
    EXPECT_GT(test::shareAboveBlack(visibility.ldr), 0.5) << technique;
  }
}

std::vector<SceneCase> everyScene() {
  std::vector<SceneCase> scenes;
  for (const BuiltinSceneInfo& info : builtinScenes()) scenes.push_back({info.name, false});
  for (const char* name : {"camp", "cave", "garage", "space"}) scenes.push_back({name, true});
  return scenes;
}

INSTANTIATE_TEST_SUITE_P(, EveryTechniqueEveryScene,
                         ::testing::Combine(::testing::ValuesIn(kTechniques),
                                            ::testing::ValuesIn(everyScene())),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name =
                               std::string(std::get<0>(info.param).name) + "_" + std::get<1>(info.param).name;
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

}  // namespace
}  // namespace lll
