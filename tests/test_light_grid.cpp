// The tiled and clustered techniques (lll's peers, lighting/light_grid.h) against the brute-force
// reference: the same images as forward on every kind of light, at every tile size and slice
// count, through overflowing bins and index arrays; and their bad options refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "awkward_lights_scene.h"
#include "core/errors.h"
#include "light_list_reference.h"
#include "lighting/light_grid.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "shared/depth_slices.h"
#include "shared/lll_types.h"
#include "test_support.h"

namespace lll {
namespace {

using GridCase = test::SceneWithLights;

struct ClusterCheck {
  uint64_t mustList = 0;  // (cluster, light) pairs where a sampled point of the light lies in the cluster
  uint64_t missing = 0;
  uint64_t listedFarAway = 0;  // listed, but farther from the cluster's volume than the light's range
  uint64_t duplicates = 0;
  double buildMismatches = -1;  // clusters grid-write did not fill as grid-count counted
};

// Every cluster's list against the lights' sampled points in its volume (tile frustum x slice).
ClusterCheck checkClusters(const Scene& scene, const RenderSettings& settings) {
  const size_t messagesBefore = test::gpuContext().validationMessages().size();
  Renderer renderer(test::gpuContext(), scene, settings);
  renderer.renderFrame(false);
  const LightGridLists grid = readLightGrid(renderer.technique());
  ClusterCheck check;
  for (const auto& [name, value] : renderer.technique().stats())
    if (name == "build_mismatches") check.buildMismatches = value;
  const gpu::FrameUniforms& u = renderer.uniforms();
  std::vector<test::ViewLight> lights;
  for (const Light& light : scene.lights) lights.push_back(test::toView(light, u.view));
  const float w = float(settings.width), h = float(settings.height), t = float(settings.tileSize);
  const float zNear = u.depthParams.x;
  for (uint32_t ty = 0; ty < grid.tilesY; ++ty) {
    for (uint32_t tx = 0; tx < grid.tilesX; ++tx) {
      const uint32_t tile = ty * grid.tilesX + tx;
      const glm::vec4 slopes =
          gpu::tileSlopes(tx * t, std::min((tx + 1) * t, w), ty * t, std::min((ty + 1) * t, h), w, h,
                          u.depthParams.z, u.depthParams.w);
      for (uint32_t slice = 0; slice < grid.slices; ++slice) {
        const glm::vec2 b =
            gpu::depthSliceBounds(grid.tileRange[tile], slice, glm::uvec2(1, grid.slices - 1), zNear);
        // Points strictly inside the slice: a point on a boundary belongs to either neighbour.
        const float lo = b.x * (1.0f + 1e-3f), hi = b.y * (1.0f - 1e-3f);
        const std::vector<uint32_t>& listed = grid.clusters[size_t(tile) * grid.slices + slice];
        std::vector<int> count(lights.size(), 0);
        for (uint32_t index : listed) {
          EXPECT_LT(index, lights.size());
          if (index >= lights.size()) continue;
          if (++count[index] == 2) ++check.duplicates;
          const test::ViewLight& l = lights[index];
          if (std::sqrt(test::referenceDistanceSquared(l.center, slopes, b.x * 0.99f, b.y * 1.01f)) >
              l.range * 1.01f)
            ++check.listedFarAway;
        }
        if (!(hi > lo)) continue;
        for (uint32_t i = 0; i < lights.size(); ++i) {
          if (test::samplesInside(lights[i], slopes, lo, hi).empty()) continue;
          ++check.mustList;
          if (count[i] == 0) ++check.missing;
        }
      }
    }
  }
  test::expectNoValidationMessagesSince(messagesBefore);
  return check;
}

struct GridListCase {
  const char* technique;
  uint32_t slices;
  uint32_t tile;
  uint32_t lights;
};

class GridLists : public ::testing::TestWithParam<GridListCase> {};

TEST_P(GridLists, MatchCpuReference) {
  const GridListCase c = GetParam();
  RenderSettings settings;
  settings.technique = c.technique;
  settings.clusterSlices = c.slices;
  settings.tileSize = c.tile;
  settings.width = 160;
  settings.height = 90;
  const ClusterCheck check = checkClusters(test::awkwardLightsScene(c.lights), settings);
  EXPECT_GT(check.mustList, 100u);
  EXPECT_EQ(check.missing, 0u) << "lights with points in a cluster that its list lacks";
  EXPECT_EQ(check.listedFarAway, 0u) << "lights listed that cannot reach their cluster";
  EXPECT_EQ(check.duplicates, 0u);
  EXPECT_EQ(check.buildMismatches, 0.0);
}

INSTANTIATE_TEST_SUITE_P(
    Grids, GridLists,
    ::testing::Values(GridListCase{"tiled", 16, 8, 40}, GridListCase{"tiled", 16, 16, 300},
                      GridListCase{"tiled", 16, 16, 1200}, GridListCase{"clustered", 16, 8, 1200},
                      GridListCase{"clustered", 16, 8, 40}, GridListCase{"clustered", 4, 16, 300},
                      GridListCase{"clustered", 32, 1, 40}),
    [](const auto& info) {
      return std::string(info.param.technique) + "_" + std::to_string(info.param.slices) + "slices_tile" +
             std::to_string(info.param.tile) + "_" + std::to_string(info.param.lights) + "lights";
    });

class GridImages : public ::testing::TestWithParam<GridCase> {};

// The atrium has glass in front of lit walls: the front slice must light it.
TEST_P(GridImages, TiledAndClusteredMatchForward) {
  const Scene scene = test::loadSceneWithLights(GetParam());
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  for (const char* technique : {"tiled", "clustered"}) {
    settings.technique = technique;
    const test::Rendered grid = test::render(scene, settings);
    test::expectWithinBound(
        grid.ldr, reference.ldr, test::kSameImage,
        std::string(technique) + " " + GetParam().scene + " " + std::to_string(GetParam().lights));
    EXPECT_GT(test::stat(grid, "index_entries_used"), 0.0) << technique;
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GridImages,
                         ::testing::Values(GridCase{"atrium", 0}, GridCase{"atrium", 1024},
                                           GridCase{"camp", 64}, GridCase{"cave", 1024},
                                           GridCase{"box-plane", 0}, GridCase{"spot-plane", 0}),
                         [](const auto& info) {
                           std::string name = info.param.scene + "_" + std::to_string(info.param.lights);
                           for (char& ch : name)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return name;
                         });

// Camera inside a light, lights under the floor and off-screen, spots and boxes turned every way:
// every tile size, and clustered with one slice up to the most.
TEST(GridImages, AwkwardLightsEveryTileAndSliceCount) {
  const Scene scene = test::awkwardLightsScene(40);
  RenderSettings settings;
  settings.width = 111;
  settings.height = 67;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  for (const uint32_t tile : {1u, 8u, 16u}) {
    settings.tileSize = tile;
    settings.technique = "tiled";
    test::expectWithinBound(test::render(scene, settings).ldr, reference.ldr, test::kSameImage,
                            "tiled awkward, tile " + std::to_string(tile));
    settings.technique = "clustered";
    for (const uint32_t slices : {1u, 4u, 32u}) {
      settings.clusterSlices = slices;
      test::expectWithinBound(
          test::render(scene, settings).ldr, reference.ldr, test::kSameImage,
          "clustered awkward, tile " + std::to_string(tile) + ", " + std::to_string(slices) + " slices");
    }
  }
}

// Many large lights on a fine grid (tile 2) overflow the bins' and the index array's first
// allocations: the frame is drawn again with room for every entry, and the image is still forward's.
TEST(GridImages, OverflowsGrowAndLoseNoLight) {
  const Scene scene = test::awkwardLightsScene(400);
  RenderSettings settings;
  settings.width = 96;
  settings.height = 54;
  settings.tileSize = 2;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  settings.technique = "clustered";
  settings.clusterSlices = 32;
  const test::Rendered grid = test::render(scene, settings);
  EXPECT_GE(grid.frame.rerenders, 1u);
  EXPECT_GE(test::stat(grid, "bin_overflows"), 1.0);
  EXPECT_GE(test::stat(grid, "overflows"), 1.0);
  EXPECT_GE(test::stat(grid, "index_capacity"), test::stat(grid, "index_entries_used"));
  test::expectWithinBound(grid.ldr, reference.ldr, test::kSameImage, "clustered after overflows");
}

// Clusters split depth: with more slices a pixel's cluster holds fewer lights (the point of them),
// and tiled's 2 slices hold more than clustered's 17.
TEST(GridImages, SlicesShortenTheLists) {
  const Scene scene = loadScene(SceneRequest{"atrium", 1024, 3});
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.technique = "tiled";
  const double tiled = test::stat(test::render(scene, settings), "mean_cluster");
  settings.technique = "clustered";
  const double clustered = test::stat(test::render(scene, settings), "mean_cluster");
  EXPECT_LT(clustered, 0.8 * tiled) << "mean lights per non-empty cluster";
}

// Thousands of large lights on one cell: every list build's per-invocation work is at its largest.
// (On lavapipe, before cells were split on CPU devices, clustered dropped lights here: llvmpipe
// ends a shader invocation's loops after 65,535 iterations in all.)
TEST(GridImages, ThousandsOfLargeLightsOnOneCellMatchForward) {
  SceneRequest request{"atrium", 2048, 1};
  request.lightRangeScale = 4.0f;
  const Scene scene = loadScene(request);
  RenderSettings settings;
  settings.width = 48;
  settings.height = 27;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  for (const char* technique : {"lll", "tiled", "clustered"}) {
    settings.technique = technique;
    const test::Rendered frame = test::render(scene, settings);
    test::expectWithinBound(frame.ldr, reference.ldr, test::kSameImage,
                            std::string(technique) + " with 2,048 large lights on one cell");
  }
}

TEST(GridImages, BadOptionsAreRefused) {
  const Scene scene = *makeBuiltinScene("plane");
  RenderSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.technique = "clustered";
  for (const uint32_t slices : {0u, 33u}) {
    settings.clusterSlices = slices;
    EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError) << slices;
  }
  settings.clusterSlices = 16;
  settings.debugView = DebugView::Bounds;  // lll's view of link depth bounds: grids have none
  for (const char* technique : {"tiled", "clustered"}) {
    settings.technique = technique;
    EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError) << technique;
  }
}

}  // namespace
}  // namespace lll
