// Glass lit in compute (--glass compute, render/lit_passes.h): the same image as the geometry pass
// where draw order is depth order, depth order where it is not, a pool that grows, every
// technique against forward, and lll's lists split by VPL class walked a class per invocation.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>

#include "render/image_compare.h"
#include "renderer/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "test_support.h"

namespace lll {
namespace {

// The grey plane under its point light, with two glass quads in one primitive (one draw): a flat
// one 1 m above the plane and, 0.3 m above it, a smaller one tilted 70 degrees, which the light over
// the near one leaves much darker. `nearFirst`: the near quad's triangles come first in the index buffer, so
// a pass that blends in draw order puts the far one over it.
Scene overlappingGlass(bool nearFirst, float nearSize = 2.0f) {
  Scene scene = *makeBuiltinScene("plane");
  Light light;
  light.position = glm::vec3(0.0f, 1.6f, 0.0f);  // close over the near pane: it is lit far more
  light.intensity = 2.0f;
  light.range = 10.0f;
  scene.lights.push_back(light);
  Material glass;
  glass.name = "glass";
  glass.baseColorFactor = glm::vec4(0.9f, 0.95f, 0.92f, 0.6f);
  glass.metallic = 0.0f;
  glass.roughness = 0.3f;
  glass.alphaMode = AlphaMode::Blend;
  scene.materials.push_back(glass);
  MeshBuilder quads("two panes");
  quads.setMaterial(uint32_t(scene.materials.size() - 1));
  const glm::mat4 nearPane = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  const glm::mat4 farPane = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.3f, 0.2f)),
                                        glm::radians(70.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  if (nearFirst) quads.addQuad(nearPane, glm::vec2(nearSize));
  quads.addQuad(farPane, glm::vec2(1.2f));  // its highest point 0.86 m up: below the near one
  if (!nearFirst) quads.addQuad(nearPane, glm::vec2(nearSize));
  scene.instances.push_back(Instance{quads.addTo(scene), glm::mat4(1.0f)});
  return scene;
}

RenderSettings small(GlassLighting glass, const std::string& technique = "forward") {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.technique = technique;
  settings.glass = glass;
  return settings;
}

// The panes' order in the index buffer decides the raster path's image, not the compute path's,
// which equals the raster path's in the order that is right (far first).
TEST(ComputeGlass, BlendsInDepthOrderWhateverTheDrawOrder) {
  const Scene nearFirst = overlappingGlass(true), farFirst = overlappingGlass(false);
  const test::Rendered computeNearFirst = test::render(nearFirst, small(GlassLighting::Compute));
  const test::Rendered computeFarFirst = test::render(farFirst, small(GlassLighting::Compute));
  const test::Rendered rasterNearFirst = test::render(nearFirst, small(GlassLighting::Raster));
  const test::Rendered rasterFarFirst = test::render(farFirst, small(GlassLighting::Raster));
  const ImageDifference order = compareImages(rasterNearFirst.ldr, rasterFarFirst.ldr);
  EXPECT_GT(order.worst, 16) << "the scene does not show the blend order: the test proves nothing";
  std::printf("[ glass    ] the raster pass's two index orders differ by up to %d of 255\n", order.worst);
  test::expectWithinBound(computeNearFirst.ldr, computeFarFirst.ldr, test::kSameImage,
                          "compute glass, index orders swapped");
  test::expectWithinBound(computeNearFirst.ldr, rasterFarFirst.ldr, test::kSameImage,
                          "compute glass against the raster pass drawing far first");
  EXPECT_EQ(test::stat(computeNearFirst, "glass-deepest-pixel"), 2.0);
}

// A pane over the whole view holds more fragments than the first pool (an eighth of the pixels, at
// least 16,384): the frame is drawn again with room, and nothing is lost.
TEST(ComputeGlass, APoolTooSmallGrowsAndTheFrameIsDrawnAgain) {
  const Scene scene = overlappingGlass(false, 40.0f);
  Renderer renderer(test::gpuContext(), scene, small(GlassLighting::Compute));
  const test::Rendered first = test::render(renderer);
  EXPECT_GE(first.frame.rerenders, 1u);
  EXPECT_EQ(test::stat(first, "glass-pool-overflows"), 1.0);
  EXPECT_GT(test::stat(first, "glass-fragments"), 160.0 * 120.0 - 1.0);
  EXPECT_GE(test::stat(first, "glass-fragment-capacity"), test::stat(first, "glass-fragments"));
  const test::Rendered second = test::render(renderer);
  EXPECT_EQ(second.frame.rerenders, 0u);
  test::expectWithinBound(first.ldr, test::render(scene, small(GlassLighting::Raster)).ldr, test::kSameImage,
                          "after growing, against the raster pass");
}

// Every technique's glass through its own lighting interface, against forward's with the glass
// lit per fragment (the reference), in the atrium, whose panes draw in depth order.
TEST(ComputeGlass, EveryTechniqueMatchesTheRasterPath) {
  const Scene scene = test::loadSceneWithLights({"atrium", 64});
  RenderSettings settings = small(GlassLighting::Raster);
  const test::Rendered reference = test::render(scene, test::reference(settings));
  for (const char* technique : {"forward", "lll", "tiled", "clustered", "deferred", "prepass"}) {
    settings = small(GlassLighting::Compute, technique);
    const test::ImageBound bound = settings.technique == "prepass" ? test::kPrepassBound : test::kSameImage;
    const test::Rendered got = test::render(scene, settings);
    EXPECT_GT(test::stat(got, "glass-fragments"), 0.0) << technique;
    test::expectWithinBound(got.ldr, reference.ldr, bound,
                            std::string("atrium glass in compute, ") + technique);
  }
}

// With --vpl-interleave lll's lists are split by VPL class, and the glass pass walks a layer's classes
// on as many invocations (the lighting interface's parts); the raster path walks them one after
// another in one fragment. A pane over the Cornell room's floor lit by the VPLs alone: the same image
// both ways, at one class and at four (a class left out darkens the pane by up to 200 of 255 here).
TEST(ComputeGlass, LllClassListsLightThePaneAsTheRasterPath) {
  SceneRequest request{"cornell"};
  request.gi.mode = GiMode::VplOnly;
  request.gi.photons = 20000;
  request.gi.vplCount = 256;
  Scene scene = loadScene(request);
  Material glass;
  glass.name = "glass";
  glass.baseColorFactor = glm::vec4(0.9f, 0.9f, 0.9f, 0.7f);
  glass.roughness = 0.6f;
  glass.alphaMode = AlphaMode::Blend;
  scene.materials.push_back(glass);
  MeshBuilder pane("pane");
  pane.setMaterial(uint32_t(scene.materials.size() - 1));
  pane.addQuad(glm::translate(glm::mat4(1.0f), glm::vec3(2.75f, 1.2f, 2.75f)), glm::vec2(3.0f));
  scene.instances.push_back(Instance{pane.addTo(scene), glm::mat4(1.0f)});
  HdrImage opaqueOnly;
  for (uint32_t interleave : {1u, 2u}) {
    RenderSettings settings = small(GlassLighting::Compute, "lll");
    settings.ambient = 0.0f;
    settings.exposure = 16.0f;
    settings.vplInterleave = interleave;
    const test::Rendered compute = test::render(scene, settings);
    settings.glass = GlassLighting::Raster;
    const test::Rendered raster = test::render(scene, settings);
    EXPECT_GT(test::stat(compute, "glass-fragments"), 160.0 * 120.0 / 8.0)
        << "the pane should fill the view's middle";
    test::expectWithinBound(compute.ldr, raster.ldr, test::kSameImage,
                            "cornell pane lit by VPLs, --vpl-interleave " + std::to_string(interleave));
  }
}

}  // namespace
}  // namespace lll
