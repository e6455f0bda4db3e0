// The lll debug views (--debug-view heatmap|bounds|tiles) against the lists read back from the GPU,
// under both shading paths (compute over the G-buffer, fragment over the geometry).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "lighting/lll.h"
#include "lighting/technique.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

// CPU copy of shaders/common/debug_colors.glsl's heat(): blue through green to red.
glm::vec3 heat(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t < 0.5f ? glm::mix(glm::vec3(0, 0, 1), glm::vec3(0, 1, 0), t * 2.0f)
                  : glm::mix(glm::vec3(0, 1, 0), glm::vec3(1, 0, 0), t * 2.0f - 1.0f);
}

struct ViewRender {
  HdrImage hdr;
  TileLightLists lists;
};

ViewRender renderView(const Scene& scene, DebugView view, LllShade shade) {
  RenderSettings settings;
  settings.technique = "lll";
  settings.width = 157;  // not a multiple of the tile: the last column and row are partial
  settings.height = 91;
  settings.debugView = view;
  settings.lllShade = shade;
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  Renderer renderer(context, scene, settings);
  renderer.renderFrame(true);
  ViewRender out{renderer.hdrImage(), readTileLightLists(renderer.technique())};
  test::expectNoValidationMessagesSince(before);
  return out;
}

Scene viewScene() {
  return loadScene(SceneRequest{"atrium", 256, 5});
}

// Every pixel of the heatmap shows the length of its tile's list (of its depth slice's, with the
// default two slices per tile) on the legend's scale (32 = red); the renderer's scale constant is
// the one the tonemap's legend uses.
class HeatmapView : public ::testing::TestWithParam<LllShade> {};

TEST_P(HeatmapView, ShowsEachTilesListLength) {
  const ViewRender r = renderView(viewScene(), DebugView::Heatmap, GetParam());
  const uint32_t tile = findTechnique("lll").defaultTile;  // renderView's (no --tile)
  uint32_t checked = 0;
  for (uint32_t y = 0; y < r.hdr.height; ++y) {
    for (uint32_t x = 0; x < r.hdr.width; ++x) {
      const glm::vec4 c = r.hdr.at(x, y);
      if (c.r == 0.0f && c.g == 0.0f && c.b == 0.0f) continue;  // background or an empty list
      // The length of the list of the pixel's depth slice: glass lies in front of the tile's surfaces.
      const size_t tileIndex = (y / tile) * r.lists.tilesX + x / tile;
      bool matched = false;
      std::string lengths;
      for (uint32_t slice = 0; slice < r.lists.slices && !matched; ++slice) {
        const size_t count = r.lists.lists[tileIndex * r.lists.slices + slice].size();
        const glm::vec3 expected = heat(float(count) / 32.0f);
        matched = count > 0 && std::abs(c.r - expected.r) <= 2e-3f && std::abs(c.g - expected.g) <= 2e-3f &&
                  std::abs(c.b - expected.b) <= 2e-3f;
        lengths += std::to_string(count) + " ";
      }
      ASSERT_TRUE(matched) << x << "," << y << ": no list of the tile has this colour's length (lists of "
                           << lengths << ")";
      ++checked;
    }
  }
  // The atrium fills the view: most pixels carry a list.
  EXPECT_GT(checked, r.hdr.width * r.hdr.height / 2);
}

INSTANTIATE_TEST_SUITE_P(Shading, HeatmapView, ::testing::Values(LllShade::Compute, LllShade::Fragment));

TEST(LllViews, TilesViewDrawsTheGridOverTheLitImage) {
  const Scene scene = viewScene();
  for (const LllShade shade : {LllShade::Compute, LllShade::Fragment}) {
    const ViewRender r = renderView(scene, DebugView::Tiles, shade);
    const uint32_t tile = findTechnique("lll").defaultTile;  // renderView's (no --tile)
    uint32_t grid = 0, gridYellow = 0, inside = 0, insideYellow = 0;
    for (uint32_t y = 0; y < r.hdr.height; ++y) {
      for (uint32_t x = 0; x < r.hdr.width; ++x) {
        const glm::vec4 c = r.hdr.at(x, y);
        if (c.r == 0.0f && c.g == 0.0f && c.b == 0.0f) continue;  // background
        const bool yellow = c.r == 1.0f && c.g == 1.0f && c.b == 0.0f;
        if (x % tile == 0 || y % tile == 0) {
          ++grid;
          gridYellow += yellow;
        } else {
          ++inside;
          insideYellow += yellow;
        }
      }
    }
    EXPECT_GT(grid, 1000u) << shade;
    EXPECT_EQ(gridYellow, grid) << shade << ": every grid line pixel on geometry is yellow";
    EXPECT_LT(insideYellow, inside / 100 + 1) << shade << ": the lit image shows between the lines";
  }
}

// The bounds view depends only on the lists and the surfaces, so both shading paths agree, and it
// shows all three states (reached, listed but out of range, unlisted).
TEST(LllViews, BoundsViewAgreesAcrossShadingPaths) {
  const Scene scene = viewScene();
  const ViewRender compute = renderView(scene, DebugView::Bounds, LllShade::Compute);
  const ViewRender fragment = renderView(scene, DebugView::Bounds, LllShade::Fragment);
  uint32_t differing = 0, grey = 0, coloured = 0;
  for (uint32_t y = 0; y < compute.hdr.height; ++y) {
    for (uint32_t x = 0; x < compute.hdr.width; ++x) {
      const glm::vec4 a = compute.hdr.at(x, y), b = fragment.hdr.at(x, y);
      if (glm::length(glm::vec3(a) - glm::vec3(b)) > 1e-3f) ++differing;
      if (a.r == 0.25f && a.g == 0.25f && a.b == 0.25f)
        ++grey;
      else if (a.r + a.g + a.b > 0.0f)
        ++coloured;
    }
  }
  // Position from depth (compute) and from interpolation (fragment) differ by rounding: a light
  // exactly at the edge of its range may flip a handful of pixels.
  EXPECT_LT(differing, compute.hdr.width * compute.hdr.height / 200);
  EXPECT_GT(grey, 0u);
  EXPECT_GT(coloured, 0u);
}

}  // namespace
}  // namespace lll
