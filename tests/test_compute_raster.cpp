// The compute rasterizer (render/compute_raster.h) against the hardware pass it replaces: the same
// frames, drawn with --raster compute and --raster hardware, must agree within a per-pixel bound
// (kRasterBound: edge ties aside, identical). Cases that take each of its paths: small triangles
// covered by their own thread, large ones listed per bin, bins that overflow, triangles clipped by
// the near plane and the guard band, back faces of single-sided and double-sided primitives.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdlib>
#include <optional>
#include <string>

#include "core/errors.h"
#include "render/compute_raster.h"
#include "render/visibility.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

// Renders with the given raster and checks that it is the one used.
test::Rendered renderWith(const Scene& scene, RenderSettings settings, RasterChoice raster) {
  settings.raster = raster;
  Renderer renderer(test::gpuContext(), scene, settings);
  EXPECT_NE(renderer.visibility(), nullptr);
  if (renderer.visibility()) {
    EXPECT_EQ(renderer.visibility()->computeRaster(), raster == RasterChoice::Compute) << raster;
  }
  return test::render(renderer);
}

void expectSameFrames(const Scene& scene, const RenderSettings& settings, const std::string& label) {
  const test::Rendered hardware = renderWith(scene, settings, RasterChoice::Hardware);
  const test::Rendered compute = renderWith(scene, settings, RasterChoice::Compute);
  test::expectWithinBound(compute.ldr, hardware.ldr, test::kRasterBound, "compute raster " + label);
}

bool skipWithoutFeatures() {
  return !ComputeRaster::problem(test::gpuContext(), 160, 90).empty();
}

struct RasterCase {
  const char* scene;
  const char* technique;
  const char* camera;  // empty: the scene's own
};

class ComputeRasterFrames : public ::testing::TestWithParam<RasterCase> {};

TEST_P(ComputeRasterFrames, MatchTheHardwarePass) {
  if (skipWithoutFeatures()) GTEST_FAIL() << ComputeRaster::problem(test::gpuContext(), 160, 90);
  const RasterCase& c = GetParam();
  const std::string path = std::string(c.scene) == "atrium" || std::string(c.scene) == "plane"
                               ? c.scene
                               : std::string(LLL_ASSETS_DIR) + "/" + c.scene + "/" + c.scene + ".gltf";
  const Scene scene = loadScene(SceneRequest{path, 16, 3});
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.technique = c.technique;
  settings.camera = c.camera;
  expectSameFrames(scene, settings, std::string(c.scene) + " " + c.technique);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, ComputeRasterFrames,
    ::testing::Values(RasterCase{"atrium", "lll", ""}, RasterCase{"atrium", "forward", ""},
                      RasterCase{"camp", "lll", ""}, RasterCase{"space", "forward", ""},
                      RasterCase{"garage", "lll", ""},
                      // Deferred's G-buffer written from the visibility buffer.
                      RasterCase{"atrium", "deferred", ""}, RasterCase{"cave", "deferred", ""},
                      // Just above a floor that runs far behind the camera: its
                      // triangles cross the near plane and leave the guard band.
                      RasterCase{"plane", "forward", "0,0.05,0,3,0,-40"},
                      // Inside the atrium's colonnade: pillars cut by the near plane.
                      RasterCase{"atrium", "lll", "-7,1.2,0.3,8,2,0.3"}),
    [](const auto& info) {
      return std::string(info.param.scene) + "_" + info.param.technique + (*info.param.camera ? "_near" : "");
    });

// Every triangle listed for the per-pixel pass (a threshold of one pixel), so that bins fill and
// overflow (a bin of the 64x36 frame gets far more than its 1,024 slots) and the whole list is
// walked there.
TEST(ComputeRaster, EveryTriangleThroughTheBinsStillMatches) {
  if (skipWithoutFeatures()) GTEST_FAIL() << ComputeRaster::problem(test::gpuContext(), 160, 90);
  const Scene scene = *makeBuiltinScene("atrium");
  RenderSettings settings;
  settings.width = 64;
  settings.height = 36;
  settings.technique = "forward";
  const test::Rendered hardware = renderWith(scene, settings, RasterChoice::Hardware);
  setenv("LLL_RASTER_OWN_BOX", "1", 1);
  const test::Rendered compute = renderWith(scene, settings, RasterChoice::Compute);
  unsetenv("LLL_RASTER_OWN_BOX");
  test::expectWithinBound(compute.ldr, hardware.ldr, test::kRasterBound,
                          "compute raster, all triangles binned");
}

// The plane with, with `glass`, a pane of glass over it and, with `masked`, two alpha-masked quads
// under the glass: one kept (alpha 0.9 over the 0.5 cutoff), one cut away (alpha 0.2).
Scene planeWith(bool glass, bool masked) {
  Scene scene = *makeBuiltinScene("plane");
  if (!glass) return scene;
  Material pane;
  pane.baseColorFactor = glm::vec4(0.8f, 0.9f, 1.0f, 0.5f);
  pane.alphaMode = AlphaMode::Blend;
  scene.materials.push_back(pane);
  MeshBuilder quads("pane");
  quads.setMaterial(uint32_t(scene.materials.size() - 1));
  quads.addQuad(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f)), glm::vec2(1.5f));
  scene.instances.push_back(Instance{quads.addTo(scene), glm::mat4(1.0f)});
  if (!masked) return scene;
  for (const float alpha : {0.9f, 0.2f}) {
    Material leaf;
    leaf.baseColorFactor = glm::vec4(0.2f, 0.7f, 0.1f, alpha);
    leaf.alphaMode = AlphaMode::Mask;
    leaf.alphaCutoff = 0.5f;
    leaf.doubleSided = true;
    scene.materials.push_back(leaf);
    MeshBuilder quad("leaf");
    quad.setMaterial(uint32_t(scene.materials.size() - 1));
    const float x = alpha > 0.5f ? -0.4f : 0.4f;
    quad.addQuad(glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.5f, 0.0f)), glm::vec2(0.6f));
    scene.instances.push_back(Instance{quad.addTo(scene), glm::mat4(1.0f)});
  }
  return scene;
}

// The D32 depth is filled from the compute rasterizer's only for a frame with a pass that uses it:
// not for lll's or tiled's frame with glass, whose passes sample the rasterizer's own R32F depth and
// test the glass fragments against it, nor for particles rendered in compute; but with alpha-masked
// primitives (the hardware draws them into the D32 depth), with particles drawn by the rasterizer (a
// depth test) and with particles about glass (the glass is drawn into a copy of the D32 depth).
// Each frame must still match the hardware pass's.
TEST(ComputeRaster, TheDepthImageIsFilledOnlyForPassesThatUseIt) {
  if (skipWithoutFeatures()) GTEST_FAIL() << ComputeRaster::problem(test::gpuContext(), 160, 90);
  struct Case {
    bool glass;
    bool masked;
    const char* technique;
    std::optional<ParticleRender> particles;  // none: no particles
    double copied;
  };
  for (const Case& c :
       {Case{true, false, "lll", std::nullopt, 0.0}, Case{true, false, "tiled", std::nullopt, 0.0},
        Case{false, false, "lll", ParticleRender::Compute, 0.0},
        Case{false, false, "lll", ParticleRender::Raster, 1.0},
        Case{true, false, "lll", ParticleRender::Compute, 1.0}, Case{true, true, "lll", std::nullopt, 1.0},
        Case{true, true, "clustered", std::nullopt, 1.0}}) {
    const std::string label =
        fmt::format("{}{}{}{}", c.technique, c.glass ? ", glass" : "", c.masked ? ", masked" : "",
                    c.particles ? fmt::format(", {} particles", *c.particles) : "");
    SCOPED_TRACE(label);
    const Scene scene = planeWith(c.glass, c.masked);
    RenderSettings settings;
    settings.width = 160;
    settings.height = 90;
    settings.technique = c.technique;
    settings.camera = "0,2.2,2.2,0,0.3,0";
    if (c.particles) {
      settings.particles = "smoke";
      settings.particleRender = *c.particles;
      settings.particleLighting = ParticleLighting::Vertex;
      settings.particleCount = 512;
      settings.particleEmitter = "0,0.2,0";
    }
    const test::Rendered hardware = renderWith(scene, settings, RasterChoice::Hardware);
    const test::Rendered compute = renderWith(scene, settings, RasterChoice::Compute);
    EXPECT_EQ(test::stat(compute, "raster-depth-copy"), c.copied);
    test::expectWithinBound(compute.ldr, hardware.ldr, test::kRasterBound, "compute raster " + label);
  }
}

// The pre-pass draws its normals and combine pass with depth EQUAL the visibility pass, and so does
// lll's fragment shading; deferred writes its G-buffer from the visibility buffer in compute and
// may use either (its frames are compared above).
TEST(ComputeRaster, TechniquesThatRedrawGeometryKeepTheHardwarePass) {
  const Scene scene = *makeBuiltinScene("plane");
  RenderSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.technique = "prepass";
  settings.raster = RasterChoice::Compute;
  EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError);
  settings.raster = RasterChoice::Auto;
  {
    Renderer renderer(test::gpuContext(), scene, settings);
    ASSERT_NE(renderer.visibility(), nullptr);
    EXPECT_FALSE(renderer.visibility()->computeRaster());
  }
  settings.technique = "deferred";
  settings.raster = RasterChoice::Compute;
  if (!skipWithoutFeatures()) {
    Renderer renderer(test::gpuContext(), scene, settings);
    ASSERT_NE(renderer.visibility(), nullptr);
    EXPECT_TRUE(renderer.visibility()->computeRaster());
  }
  settings.technique = "lll";
  settings.lllShade = LllShade::Fragment;
  settings.raster = RasterChoice::Compute;
  EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError);
  settings.surfaces = SurfaceSource::Gbuffer;
  settings.lllShade = LllShade::Compute;
  EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError);
}

}  // namespace
}  // namespace lll

namespace lll {
namespace {

// 8 bytes of key per pixel: an image whose keys exceed the device's storage-buffer range is
// refused with a message naming the size and the limit (lavapipe: 128 MiB, 4096x4096 at most).
TEST(ComputeRaster, KeysBeyondTheStorageBufferLimitAreRefused) {
  Context& context = test::gpuContext();
  const VkDeviceSize limit = context.properties().limits.maxStorageBufferRange;
  for (const uint32_t size : {1024u, 8192u}) {
    const std::string problem = ComputeRaster::problem(context, size, size);
    if (VkDeviceSize(size) * size * 8 > limit) {
      EXPECT_NE(problem.find(fmt::format("{}x{}", size, size)), std::string::npos) << problem;
      EXPECT_NE(problem.find("storage buffer limit"), std::string::npos) << problem;
    } else if (context.computeRasterFeatures()) {
      EXPECT_EQ(problem, "") << size;
    }
  }
}

}  // namespace
}  // namespace lll
