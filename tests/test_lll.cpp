// The light linked list against independent references: per-tile light sets against a CPU
// reference computed from the same tile depths, and images against the forward renderer.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>
#include <random>

#include "awkward_lights_scene.h"
#include "core/errors.h"
#include "light_list_reference.h"
#include "lighting/light_bins.h"
#include "lighting/lll.h"
#include "scene/builtin_scenes.h"
#include "scene/lights.h"
#include "scene/scene_source.h"
#include "shared/depth_slices.h"
#include "shared/lll_types.h"
#include "test_support.h"

namespace lll {
namespace {

using test::referenceDistanceSquared;
using test::samplesInside;
using test::toView;
using test::ViewLight;

using test::kPi;

struct ListCheck {
  uint32_t mustList = 0;  // (tile, light) pairs the reference requires
  uint32_t listed = 0;
  uint32_t missing = 0;
  uint32_t beyondMargin = 0;
  uint32_t depthOutside = 0;
  uint32_t outsideSlice = 0;  // links in a depth slice their bounds do not overlap
  uint32_t slicedOut = 0;     // (tile, slice, light): listed in another slice of the tile, not this one
  uint32_t deepTiles = 0;     // tiles whose opaque depth range has more than one slice
};

// How far beyond its range a fill may list a light: the shells' coarseness and the tile inflation.
float allowedDistance(LllFill fill, const ViewLight& l, const RenderSettings& s, const Renderer& r) {
  const float tanY = r.uniforms().depthParams.w;
  const float inflation = std::max(l.center.z + l.range, 0.0f) * 1.1f * std::sqrt(2.0f) * 0.5f *
                          float(s.tileSize) * 2.0f * tanY / float(s.height);
  if (fill == LllFill::Compute) return l.range * 1.001f + 1e-4f;
  if (fill == LllFill::Ray || !l.spot || l.cosOuter < 0.5f)
    return (l.range + inflation) * (fill == LllFill::Ray ? 1.001f : 1.3f);
  const float sinA = std::sqrt(1.0f - l.cosOuter * l.cosOuter), back = inflation / sinA;
  const float len = l.range + inflation + back, radius = len * sinA / l.cosOuter / std::cos(kPi / 16.0f);
  return back + std::sqrt(len * len + radius * radius);
}

ListCheck checkLists(const Scene& scene, const RenderSettings& settings,
                     std::vector<std::pair<std::string, double>>* stats = nullptr) {
  Context& context = test::gpuContext();
  Renderer renderer(context, scene, settings);
  renderer.renderFrame(false);
  if (stats) *stats = renderer.technique().stats();
  const TileLightLists lists = readTileLightLists(renderer.technique());
  EXPECT_EQ(lists.slices, std::max(settings.lllSlices, 1u));
  const gpu::FrameUniforms& u = renderer.uniforms();
  std::vector<ViewLight> lights;
  for (const Light& light : scene.lights) lights.push_back(toView(light, u.view));
  ListCheck check;
  const float w = float(settings.width), h = float(settings.height), t = float(settings.tileSize);
  const float zNear = u.depthParams.x;
  for (uint32_t ty = 0; ty < lists.tilesY; ++ty) {
    for (uint32_t tx = 0; tx < lists.tilesX; ++tx) {
      const uint32_t index = ty * lists.tilesX + tx;
      const glm::vec4 slopes =
          gpu::tileSlopes(tx * t, std::min((tx + 1) * t, w), ty * t, std::min((ty + 1) * t, h), w, h,
                          u.depthParams.z, u.depthParams.w);
      const float zFar = lists.tileRange[index].y;
      const glm::uvec2 split = gpu::lllSliceSplit(lists.tileRange[index], lists.slices);
      check.deepTiles += split.y > 1;
      std::vector<float> tileDistance(lights.size());
      for (uint32_t i = 0; i < lights.size(); ++i)
        tileDistance[i] = std::sqrt(referenceDistanceSquared(lights[i].center, slopes, zNear, zFar));
      std::vector<uint32_t> slicesListing(lights.size(), 0);
      for (uint32_t slice = 0; slice < lists.slices; ++slice)
        for (const LightLinkRecord& link : lists.lists[size_t(index) * lists.slices + slice])
          if (link.light < lights.size()) ++slicesListing[link.light];
      for (uint32_t count : slicesListing)
        if (count > 0) check.slicedOut += lists.slices - count;
      for (uint32_t slice = 0; slice < lists.slices; ++slice) {
        // The slice's volume; with slices, only points strictly inside it (a point on a boundary
        // belongs to either neighbour).
        const glm::vec2 raw = gpu::depthSliceBounds(lists.tileRange[index], slice, split, zNear);
        glm::vec2 b = raw;
        if (lists.slices > 1) b = {std::max(b.x * (1.0f + 1e-3f), zNear), b.y * (1.0f - 1e-3f)};
        std::vector<const LightLinkRecord*> byLight(lights.size(), nullptr);
        for (const LightLinkRecord& link : lists.lists[size_t(index) * lists.slices + slice]) {
          EXPECT_LT(link.light, lights.size());
          if (link.light < lights.size()) byLight[link.light] = &link;
          ++check.listed;
          // A link in a slice its depth bounds do not reach lights no point there.
          if (lists.slices > 1 &&
              (link.maxDepth < raw.x * (1.0f - 1e-3f) || link.minDepth > raw.y * (1.0f + 1e-3f)))
            ++check.outsideSlice;
        }
        for (uint32_t i = 0; i < lights.size(); ++i) {
          const ViewLight& l = lights[i];
          const float dist = tileDistance[i];
          // A light out of the tile's reach is out of each slice's (the slices lie within the tile).
          const float sliceDist = b.y > b.x && (lists.slices == 1 || dist <= l.range)
                                      ? std::sqrt(referenceDistanceSquared(l.center, slopes, b.x, b.y))
                                      : 1e30f;
          const std::vector<glm::vec3> inside =
              sliceDist <= l.range ? samplesInside(l, slopes, b.x, b.y) : std::vector<glm::vec3>{};
          const bool must = !inside.empty() || (!l.spot && !l.box && sliceDist <= l.range * 0.999f);
          check.mustList += must;
          const LightLinkRecord* link = byLight[i];
          if (must && !link) ++check.missing;
          // Shells: a front face overwritten in the bounds buffer by another light counts as clipped by
          // the near plane (Bezrati 1.3.2), so such a link ignores the tile's depth: measure to the
          // tile's whole frustum.
          const float marginDistance =
              settings.lllFill == LllFill::Shells
                  ? std::sqrt(referenceDistanceSquared(l.center, slopes, zNear, 1e4f))
                  : dist;
          if (link && marginDistance > allowedDistance(settings.lllFill, l, settings, renderer))
            ++check.beyondMargin;
          // Every sampled point of the light in this tile lies within the link's depth bounds.
          for (const glm::vec3& p : link ? inside : std::vector<glm::vec3>{})
            if (p.z < link->minDepth - 1e-3f * p.z || p.z > link->maxDepth + 1e-3f * p.z)
              ++check.depthOutside;
        }
      }
    }
  }
  EXPECT_TRUE(context.validationMessages().empty());
  return check;
}

// An lll render of `width` x `height` with `slices` lists per tile.
RenderSettings listSettings(LllFill fill, uint32_t tile, uint32_t width, uint32_t height, uint32_t slices,
                            uint32_t fillSplits = 0) {
  RenderSettings settings;
  settings.technique = "lll";
  settings.lllFill = fill;
  settings.tileSize = tile;
  settings.width = width;
  settings.height = height;
  settings.lllSlices = slices;
  settings.lllFillSplits = fillSplits;
  return settings;
}

// Every light the reference requires is listed; no link lies beyond the fill's documented margin,
// misses a sampled point of its light, or sits in a depth slice its bounds do not reach.
void expectListsHoldEveryLight(const ListCheck& check, const std::string& what) {
  EXPECT_EQ(check.missing, 0u) << what << ": lights the reference requires but the fill did not list";
  EXPECT_EQ(check.beyondMargin, 0u) << what
                                    << ": lights listed farther away than the fill's documented margin";
  EXPECT_EQ(check.depthOutside, 0u) << what << ": light points outside their link's depth bounds";
  EXPECT_EQ(check.outsideSlice, 0u) << what << ": links in depth slices their bounds do not reach";
}

struct ListCase {
  LllFill fill;
  uint32_t tile;
  uint32_t width;
  uint32_t height;
  uint32_t fillSplits = 0;  // compute fill: workgroups per cell (0: by light count, here 1)
  uint32_t slices = 1;      // --lll-slices
};

class LllLists : public ::testing::TestWithParam<ListCase> {};

TEST_P(LllLists, MatchCpuReference) {
  const ListCase c = GetParam();
  const ListCheck check = checkLists(test::awkwardLightsScene(40),
                                     listSettings(c.fill, c.tile, c.width, c.height, c.slices, c.fillSplits));
  EXPECT_GT(check.mustList, 100u);  // the scene really exercises the lists
  expectListsHoldEveryLight(check, std::string(nameOf(c.fill)));
  if (c.slices > 1) {
    EXPECT_GT(check.slicedOut, check.listed / 4) << "the slices should keep most lights out of most lists";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Fills, LllLists,
    ::testing::Values(
        ListCase{LllFill::Compute, 8, 333, 197}, ListCase{LllFill::Ray, 8, 333, 197},
        ListCase{LllFill::Shells, 8, 333, 197}, ListCase{LllFill::Compute, 16, 333, 197},
        ListCase{LllFill::Ray, 16, 333, 197}, ListCase{LllFill::Shells, 16, 333, 197},
        ListCase{LllFill::Compute, 1, 111, 67}, ListCase{LllFill::Ray, 1, 111, 67},
        ListCase{LllFill::Shells, 1, 111, 67}, ListCase{LllFill::Compute, 8, 333, 197, 3},
        ListCase{LllFill::Compute, 1, 111, 67, 16}, ListCase{LllFill::Compute, 8, 333, 197, 0, 16},
        ListCase{LllFill::Compute, 8, 333, 197, 3, 16}, ListCase{LllFill::Compute, 1, 111, 67, 0, 32},
        ListCase{LllFill::Ray, 16, 333, 197, 0, 8}, ListCase{LllFill::Shells, 8, 333, 197, 0, 4}),
    [](const auto& info) {
      return std::string(nameOf(info.param.fill)) + "_tile" + std::to_string(info.param.tile) + "_" +
             std::to_string(info.param.width) + "x" + std::to_string(info.param.height) +
             (info.param.fillSplits ? "_splits" + std::to_string(info.param.fillSplits) : "") +
             (info.param.slices > 1 ? "_slices" + std::to_string(info.param.slices) : "");
    });

// Depth-sliced lists where tiles are deep: the atrium's columns and arches in front of its walls
// split the tiles' opaque depth ranges as well as the depth in front of them.
TEST(LllLists, SlicedListsOfDeepTilesMatchCpuReference) {
  const ListCheck check =
      checkLists(test::loadSceneWithLights({"atrium", 300}), listSettings(LllFill::Compute, 16, 192, 108, 8));
  EXPECT_GT(check.mustList, 1000u);
  expectListsHoldEveryLight(check, "atrium, 8 slices");
  EXPECT_GT(check.deepTiles, 10u) << "the atrium should have tiles with deep opaque ranges";
  EXPECT_GT(check.slicedOut, check.listed / 4);
}

// A cell's lights split among workgroups (--lll-fill-splits): 1,200 lights on two cells of 8x8
// 16-pixel tiles, each cell's lights in 8 parts, whose chains are spliced at the heads (one list per
// tile) or pushed at the slices' heads (sliced).
TEST(LllLists, CellsSharedByWorkgroupsLoseNoLight) {
  for (const uint32_t slices : {1u, 4u}) {
    std::vector<std::pair<std::string, double>> stats;
    const ListCheck check = checkLists(test::awkwardLightsScene(1200),
                                       listSettings(LllFill::Compute, 16, 160, 90, slices, 8), &stats);
    double binned = 0.0;
    for (const auto& [name, value] : stats)
      if (name == "bin_entries_used") binned = value;
    EXPECT_GT(binned, 2.0 * 8.0 * 64.0) << "each part of the two cells should hold a batch of lights";
    EXPECT_GT(check.mustList, 1000u);
    expectListsHoldEveryLight(check, std::to_string(slices) + " lists per tile");
  }
}

// Up to kUnbinnedLights lights the compute fill builds no bins and every workgroup reads every
// light (lighting/light_bins.h); one light more and it bins them. Both must list every light the
// reference requires, at the threshold and past it, with one list per tile and with slices.
TEST(LllLists, FewLightsAreListedWithoutBins) {
  // The scene adds its own awkward lights to the random ones asked for.
  const uint32_t own = uint32_t(test::awkwardLightsScene(0).lights.size());
  for (const uint32_t lights : {kUnbinnedLights, kUnbinnedLights + 1}) {
    const Scene scene = test::awkwardLightsScene(lights - own);
    ASSERT_EQ(scene.lights.size(), lights);
    for (const uint32_t slices : {1u, 4u}) {
      std::vector<std::pair<std::string, double>> stats;
      const ListCheck check = checkLists(scene, listSettings(LllFill::Compute, 8, 160, 90, slices), &stats);
      double unbinned = -1.0, binned = -1.0;
      for (const auto& [name, value] : stats) {
        if (name == "bins_unbinned") unbinned = value;
        if (name == "bin_entries_used") binned = value;
      }
      const bool few = lights <= kUnbinnedLights;
      EXPECT_EQ(unbinned, few ? 1.0 : 0.0) << lights << " lights";
      if (few)
        EXPECT_EQ(binned, 0.0) << "no bin entries without bins";
      else
        EXPECT_GT(binned, 0.0) << "past the threshold the lights are binned";
      EXPECT_GT(check.mustList, 100u);
      expectListsHoldEveryLight(check,
                                std::to_string(lights) + " lights, " + std::to_string(slices) + " slices");
    }
  }
}

// The compute fill reads the lights binned to its cell (lighting/light_bins.h). Many large lights
// on a fine grid overflow the bins' first allocation: the frame must be drawn again with room for
// every entry, and the lists must still hold every light the reference requires.
TEST(LllLists, OverflowingBinsGrowAndLoseNoLight) {
  std::vector<std::pair<std::string, double>> stats;
  const ListCheck check =
      checkLists(test::awkwardLightsScene(400),
                 listSettings(LllFill::Compute, 2, 96, 54, RenderSettings{}.lllSlices), &stats);
  double overflows = -1.0, used = 0.0, capacity = 0.0;
  for (const auto& [name, value] : stats) {
    if (name == "bin_overflows") overflows = value;
    if (name == "bin_entries_used") used = value;
    if (name == "bin_entries_capacity") capacity = value;
  }
  EXPECT_GE(overflows, 1.0) << "the scene should overflow the bins' first allocation";
  EXPECT_GE(capacity, used);
  EXPECT_GT(check.mustList, 1000u);
  expectListsHoldEveryLight(check, "after the bins grew");
}

// --- Images: lll must reproduce forward, the brute-force reference --------------------------------

using ImageCase = test::SceneWithLights;

// Each fill with the default compute shading, and the chapter's fragment shading with one fill
// (fill and shading are independent: the lists are the same).
// Depth-sliced lists (--lll-slices) with the compute fill and with a raster fill.
struct Variant {
  LllFill fill;
  LllShade shade;
  uint32_t slices = 1;
};
constexpr Variant kVariants[] = {
    {LllFill::Compute, LllShade::Compute},     {LllFill::Ray, LllShade::Compute},
    {LllFill::Shells, LllShade::Compute},      {LllFill::Compute, LllShade::Fragment},
    {LllFill::Compute, LllShade::Compute, 16}, {LllFill::Shells, LllShade::Fragment, 8}};

std::string variantName(const Variant& v) {
  return fmt::format("{}/{}", v.fill, v.shade) + (v.slices > 1 ? "/slices" + std::to_string(v.slices) : "");
}

class LllImages : public ::testing::TestWithParam<ImageCase> {};

TEST_P(LllImages, EveryFillMatchesForward) {
  const Scene scene = test::loadSceneWithLights(GetParam());
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  settings.technique = "lll";
  for (const Variant& v : kVariants) {
    settings.lllFill = v.fill;
    settings.lllShade = v.shade;
    settings.lllSlices = v.slices;
    const test::Rendered lll = test::render(scene, settings);
    test::expectWithinBound(
        lll.ldr, reference.ldr, test::kSameImage,
        "lll/" + variantName(v) + " " + GetParam().scene + " " + std::to_string(GetParam().lights));
    EXPECT_GT(test::stat(lll, "links_used"), 0.0) << variantName(v);
    EXPECT_EQ(test::stat(lll, "link_bytes_each"), scene.lights.size() > 256 ? 16.0 : 8.0) << variantName(v);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, LllImages,
                         ::testing::Values(ImageCase{"atrium", 0}, ImageCase{"atrium", 1024},
                                           ImageCase{"camp", 64}, ImageCase{"cave", 64},
                                           ImageCase{"garage", 64}, ImageCase{"space", 64},
                                           ImageCase{"camp", 1024}, ImageCase{"cave", 1024},
                                           ImageCase{"garage", 1024}, ImageCase{"space", 1024}),
                         [](const auto& info) {
                           return info.param.scene + "_" + std::to_string(info.param.lights);
                         });

TEST(LllImages, AwkwardLightsMatchForward) {
  // Camera inside a light, lights under the floor and off-screen, spots of every width.
  const Scene scene = test::awkwardLightsScene(40);
  RenderSettings settings;
  settings.width = 128;
  settings.height = 128;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  settings.technique = "lll";
  for (const Variant& v : kVariants) {
    settings.lllFill = v.fill;
    settings.lllShade = v.shade;
    settings.lllSlices = v.slices;
    test::expectWithinBound(test::render(scene, settings).ldr, reference.ldr, test::kSameImage,
                            "lll/" + variantName(v) + " awkward lights");
  }
  // --lll-records: the opaque shading reads listed lights' records through the uniform block or
  // the storage buffer, spots' and boxes' fields too, to the same image; auto reads storage on a
  // CPU device.
  settings.lllFill = LllFill::Compute;
  settings.lllShade = LllShade::Compute;
  settings.lllSlices = 1;
  for (const LllRecords records : {LllRecords::Uniform, LllRecords::Storage, LllRecords::Auto}) {
    settings.lllRecords = records;
    const test::Rendered lll = test::render(scene, settings);
    const bool uniform =
        records == LllRecords::Uniform || (records == LllRecords::Auto && !test::gpuContext().isCpuDevice());
    EXPECT_EQ(test::stat(lll, "records_from_uniform_block"), uniform ? 1.0 : 0.0) << records;
    test::expectWithinBound(lll.ldr, reference.ldr, test::kSameImage,
                            fmt::format("lll/compute records from {} awkward lights", records));
  }
}

// The atrium at 160x90 through lll with `settings` and a first link pool of one link a tile (far
// too small: the first frame must overflow), with each of `fills`, against forward; `check` adds
// a test's own expectations of each render.
void expectOverflowingPoolMatches(RenderSettings settings, std::initializer_list<LllFill> fills,
                                  const std::string& what,
                                  const std::function<void(const test::Rendered&, LllFill)>& check) {
  const Scene scene = *makeBuiltinScene("atrium");
  settings.width = 160;
  settings.height = 90;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  settings.technique = "lll";
  settings.linksPerTile = 1;
  for (const LllFill fill : fills) {
    settings.lllFill = fill;
    const test::Rendered lll = test::render(scene, settings);
    EXPECT_GE(lll.frame.rerenders, 1u) << fill;
    check(lll, fill);
    test::expectWithinBound(lll.ldr, reference.ldr, test::kSameImage, fmt::format("lll/{} {}", fill, what));
  }
}

TEST(LllImages, TinyPoolGrowsAndStillMatches) {
  expectOverflowingPoolMatches(
      {}, {LllFill::Compute, LllFill::Ray, LllFill::Shells}, "grown pool",
      [](const test::Rendered& lll, LllFill fill) {
        EXPECT_GE(test::stat(lll, "overflows"), 1.0) << fill;
        EXPECT_GE(test::stat(lll, "link_pool_capacity"), test::stat(lll, "links_used")) << fill;
      });
}

TEST(LllImages, CompactPoolOutgrownMovesToWideLinksAndStillMatches) {
  // A compact pool that may hold only 128 links: the first frame outgrows it, and --lll-link auto
  // must move to wide links, with every pass that reads them (the fills, opaque shading, glass)
  // compiled again for that format (kLinkFormat, common/lll_data.glsl).
  RenderSettings settings;
  settings.lllCompactLinkLimit = 128;  // the first pool: 60 tiles x 2 slices
  expectOverflowingPoolMatches(settings, {LllFill::Compute, LllFill::Shells},
                               "compact pool moved to wide links",
                               [](const test::Rendered& lll, LllFill fill) {
                                 EXPECT_GT(test::stat(lll, "links_used"), 128.0) << fill;
                                 EXPECT_EQ(test::stat(lll, "link_bytes_each"), 16.0) << fill;
                               });
}

TEST(LllImages, MoreSlicesThanTheMostAreRefused) {
  RenderSettings settings;
  settings.technique = "lll";
  settings.width = 32;
  settings.height = 32;
  settings.lllSlices = gpu::kMaxLllSlices + 1;
  try {
    Renderer(test::gpuContext(), test::awkwardLightsScene(4), settings);
    ADD_FAILURE() << "33 slices accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--lll-slices 33"), std::string::npos) << e.what();
  }
}

// A list head per tile and slice: past the device's largest storage buffer the technique is
// refused, naming the heads and the option, before it creates anything.
TEST(LllImages, SliceHeadsPastTheDeviceLimitAreRefused) {
  Context& context = test::gpuContext();
  const uint64_t limit = context.properties().limits.maxStorageBufferRange;
  RenderSettings settings;
  settings.technique = "lll";
  settings.tileSize = 1;
  settings.lllSlices = gpu::kMaxLllSlices;
  settings.width = 4096;  // one more row of tiles than 32 heads a tile fit in the limit
  settings.height = uint32_t(limit / (4ull * gpu::kMaxLllSlices) / settings.width + 1);
  try {
    Renderer(context, *makeBuiltinScene("plane"), settings);
    ADD_FAILURE() << settings.width << "x" << settings.height << " with 32 slices accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("heads"), std::string::npos) << message;
    EXPECT_NE(message.find("--lll-slices"), std::string::npos) << message;
  }
}

// --lll-records uniform past the uniform block's 256 records is refused, naming it.
TEST(LllImages, UniformRecordsRefuseTooManyLights) {
  const Scene scene = test::awkwardLightsScene(gpu::kUniformLightRecords);
  ASSERT_GT(scene.lights.size(), gpu::kUniformLightRecords);
  RenderSettings settings;
  settings.technique = "lll";
  settings.lllRecords = LllRecords::Uniform;
  settings.width = 32;
  settings.height = 32;
  try {
    Renderer(test::gpuContext(), scene, settings);
    ADD_FAILURE() << "uniform records of " << scene.lights.size() << " lights accepted";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find(fmt::format("--lll-records uniform: {} lights", scene.lights.size())),
        std::string::npos)
        << e.what();
  }
}

TEST(LllImages, CompactLinksRefuseTooManyLights) {
  Scene scene = test::awkwardLightsScene(300);
  RenderSettings settings;
  settings.technique = "lll";
  settings.lllLink = LllLink::Compact;
  settings.width = 32;
  settings.height = 32;
  EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError);
}

}  // namespace
}  // namespace lll
