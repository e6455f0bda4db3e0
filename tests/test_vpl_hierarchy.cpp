// The lighting grid hierarchy over the VPLs (gi/vpl_hierarchy.h): its levels' bands add up to 1 at
// every distance, every level keeps the deposits' flux, level 0 is the single-grid merge, a level
// that groups the deposits as the one below is folded into it; rendered: the Cornell room against
// the path-traced reference with lists far shorter than whole-room ranges need; the moving lights'
// re-trace over every level; the command line's options. (The analytic sphere room and every
// technique against forward, through the hierarchy too: test_gi.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli_test_support.h"
#include "gi/light_falloff.h"
#include "gi/moving_vpls.h"
#include "gi/path_tracer.h"
#include "gi/photon_walk.h"
#include "gi/photons.h"
#include "gi/ray_scene.h"
#include "gi/vpl_hierarchy.h"
#include "gi_test_support.h"
#include "render/image_compare.h"
#include "scene/builtin_gi_scenes.h"
#include "shared/limits.h"
#include "test_support.h"

namespace lll {
namespace {

using test::kPi;

std::vector<gi::PhotonDeposit> cornellDeposits(uint32_t photons, gi::PhotonStats* stats = nullptr) {
  const Scene scene = builtin::makeCornell();
  const gi::RayScene rays(scene);
  gi::VplOptions options;
  options.photons = photons;
  return gi::tracePhotons(rays, scene, options, stats);
}

// The sum of every level's band at distance d: what a deposit alone in its cell on every level gets.
float bandSum(const std::vector<gi::VplLevel>& levels, float d) {
  float sum = 0.0f;
  for (const gi::VplLevel& l : levels) sum += gi::hierarchyBand(d, l.inner, l.outer);
  return sum;
}

void expectBandsPartitionDistance(const std::vector<gi::VplLevel>& levels, float reach) {
  for (int i = 0; i <= 4000; ++i) {
    const float d = reach * float(i) / 4000.0f;
    ASSERT_NEAR(bandSum(levels, d), 1.0f, 1e-5f) << "at " << d << " m";
  }
}

glm::vec3 fluxOf(const std::vector<Light>& vpls, size_t first, size_t end) {
  glm::vec3 flux(0.0f);
  for (size_t i = first; i < end; ++i) flux += vpls[i].color * vpls[i].intensity * kPi;
  return flux;
}

TEST(VplHierarchy, LevelsPartitionEveryDistanceAndKeepTheFlux) {
  gi::PhotonStats traced;
  const std::vector<gi::PhotonDeposit> deposits = cornellDeposits(20000, &traced);
  const Bounds bounds = gi::walk::depositBounds(deposits);
  const float diagonal = gi::walk::boundsDiagonal(bounds);
  const float finest = gi::walk::mergeCellEdge(deposits, 512, bounds.min, diagonal);
  const float reach = 1.5f * diagonal, alpha = 1.5f, minNear = 1e-3f;
  const gi::VplHierarchy h = gi::buildVplHierarchy(deposits, bounds.min, finest, alpha, reach, minNear);
  ASSERT_GE(h.levels.size(), 3u);
  ASSERT_EQ(h.firstLight.size(), h.levels.size() + 1);
  EXPECT_EQ(h.firstLight.back(), h.lights.size());
  std::printf(
      "[ lgh ] cornell, 20,000 photons, finest edge %.3f m, alpha %.1f: %zu levels, %zu VPLs (level 0: %u)\n",
      finest, alpha, h.levels.size(), h.lights.size(), h.firstLight[1]);

  // The levels: edges doubling (or more, where a level was folded), bands that meet, the top one
  // at full weight out to the reach.
  EXPECT_EQ(h.levels[0].cellEdge, finest);
  EXPECT_EQ(h.levels[0].inner, 0.0f);
  for (size_t l = 0; l + 1 < h.levels.size(); ++l) {
    const float ratio = h.levels[l + 1].cellEdge / h.levels[l].cellEdge;
    EXPECT_EQ(ratio, std::exp2(std::round(std::log2(ratio)))) << "a power of two";
    EXPECT_GE(ratio, 2.0f);
    EXPECT_EQ(h.levels[l + 1].inner, h.levels[l].outer) << l;
    EXPECT_FLOAT_EQ(h.levels[l].outer, alpha * h.levels[l + 1].cellEdge / 2.0f) << l;
    EXPECT_LT(h.firstLight[l + 2] - h.firstLight[l + 1], h.firstLight[l + 1] - h.firstLight[l])
        << "each level has fewer VPLs than the one below";
  }
  const gi::VplLevel& top = h.levels.back();
  EXPECT_GE(top.outer, reach);
  EXPECT_TRUE(h.lights.size() - h.firstLight[h.levels.size() - 1] <= gi::kHierarchyTopLights ||
              alpha * top.cellEdge >= reach);
  expectBandsPartitionDistance(h.levels, reach);

  // Every level holds all of the deposited flux; level 0 is the single-grid merge at its edge.
  for (size_t l = 0; l < h.levels.size(); ++l) {
    const glm::vec3 flux = fluxOf(h.lights, h.firstLight[l], h.firstLight[l + 1]);
    EXPECT_NEAR(flux.r, traced.depositedFlux.r, 1e-3f * traced.depositedFlux.r) << "level " << l;
    EXPECT_NEAR(flux.b, traced.depositedFlux.b, 1e-3f * traced.depositedFlux.b) << "level " << l;
    for (uint32_t i = h.firstLight[l]; i < h.firstLight[l + 1]; ++i) {
      const Light& v = h.lights[i];
      ASSERT_EQ(v.type, LightType::Vpl);
      EXPECT_EQ(v.bandInner, h.levels[l].inner);
      EXPECT_EQ(v.bandOuter, h.levels[l].outer);
      EXPECT_EQ(v.range, 2.0f * h.levels[l].outer);
      EXPECT_EQ(v.nearDistance, std::max(0.5f * h.levels[l].cellEdge, minNear));
    }
  }
  const std::vector<Light> merged = gi::walk::mergeOnGrid(deposits, bounds.min, finest, 0.0f, {0.0f, 1.0f});
  ASSERT_EQ(merged.size(), h.firstLight[1]);
  for (size_t i = 0; i < merged.size(); ++i) {
    ASSERT_EQ(merged[i].position, h.lights[i].position) << i;
    ASSERT_EQ(merged[i].intensity, h.lights[i].intensity) << i;
  }
}

// Twelve deposits (three rows of four) that a grid of edge 2 keeps apart as one of edge 1 does: level
// 1 would repeat level 0, so level 0 takes its band; the grid of edge 4 pairs them and, with six
// VPLs, is the top level.
TEST(VplHierarchy, ALevelThatGroupsAsTheOneBelowIsFolded) {
  std::vector<gi::PhotonDeposit> deposits;
  for (const float z : {0.5f, 16.5f, 32.5f})
    for (const float x : {0.5f, 2.5f, 8.5f, 10.5f}) deposits.push_back({{x, 0.5f, z}, {0, 1, 0}, {1, 1, 1}});
  const float alpha = 1.5f, reach = 40.0f;
  const gi::VplHierarchy h = gi::buildVplHierarchy(deposits, glm::vec3(0.0f), 1.0f, alpha, reach, 0.01f);
  ASSERT_EQ(h.levels.size(), 2u);
  EXPECT_EQ(h.levels[0].cellEdge, 1.0f);
  EXPECT_EQ(h.levels[0].outer, alpha * 2.0f);
  EXPECT_EQ(h.levels[1].cellEdge, 4.0f);
  EXPECT_EQ(h.levels[1].inner, alpha * 2.0f);
  EXPECT_EQ(h.levels[1].outer, reach);
  ASSERT_EQ(h.firstLight, (std::vector<uint32_t>{0, 12, 18}));
  EXPECT_EQ(h.lights[12].position, glm::vec3(1.5f, 0.5f, 0.5f));  // a pair's flux-weighted centre
  EXPECT_EQ(h.lights[15].position, glm::vec3(9.5f, 0.5f, 0.5f));  // in key order: x first
  expectBandsPartitionDistance(h.levels, reach);
  // A deposit alone gets one level, full weight from the deposit out to the reach.
  const gi::VplHierarchy one =
      gi::buildVplHierarchy({deposits[0]}, glm::vec3(0.0f), 1.0f, alpha, reach, 0.01f);
  ASSERT_EQ(one.levels.size(), 1u);
  EXPECT_EQ(one.levels[0].inner, 0.0f);
  EXPECT_EQ(one.levels[0].outer, reach);
  EXPECT_TRUE(gi::buildVplHierarchy({}, glm::vec3(0.0f), 1.0f, alpha, reach, 0.01f).lights.empty());
}

// What the hierarchy is for: the Cornell room's indirect light as accurate as with VPLs that reach
// the whole room, through light lists a fraction as long.
TEST(VplHierarchy, CornellMatchesTheReferenceWithShortLists) {
  RenderSettings settings;
  settings.width = 64;
  settings.height = 48;
  settings.technique = "lll";
  settings.tileSize = 4;
  settings.ambient = 0.0f;
  const HdrImage reference = test::cornellIndirectReference(settings.width, settings.height);
  struct Run {
    double error, meanList;
  };
  auto run = [&](GiHierarchy hierarchy, float cutoff) {
    SceneRequest request{"cornell"};
    request.gi.mode = GiMode::VplOnly;
    request.gi.vplCount = 2048;
    request.gi.vplCutoff = cutoff;
    request.gi.hierarchy = hierarchy;
    request.gi.vplAlpha = 1.5f;
    const test::Rendered r = test::render(loadScene(request), settings);
    // 8x8-pixel blocks: the reference's per-pixel noise averages down to a few percent.
    return Run{relativeBlockError(r.hdr, reference, 8), test::stat(r, "mean_list")};
  };
  const Run whole = run(GiHierarchy::None, 1e-6f), cut = run(GiHierarchy::None, gi::kDefaultVplCutoff),
            lgh = run(GiHierarchy::Grid, 1e-6f);
  std::printf(
      "[ lgh ] cornell, 2,048 VPLs: error %.4f whole-room ranges (mean list %.0f), %.4f default cutoff "
      "(%.0f), %.4f hierarchy (%.0f)\n",
      whole.error, whole.meanList, cut.error, cut.meanList, lgh.error, lgh.meanList);
  EXPECT_LT(lgh.error, 0.05);
  EXPECT_LT(lgh.error, whole.error + 0.02) << "about as accurate as whole-room ranges";
  EXPECT_LT(lgh.meanList, 0.25 * whole.meanList) << "through far shorter lists";
}

// ---- moving lights: every level's cells follow ----

SceneRequest movingCornell(float seconds) {
  SceneRequest request{"cornell"};
  request.extraLights = 3;
  request.seed = 5;
  request.movingLights = true;
  request.time = seconds;
  return request;
}

gi::VplOptions hierarchyTrace() {
  gi::VplOptions options;
  options.photons = 20000;
  options.vplCount = 512;
  options.seed = 5;
  options.hierarchy = true;
  options.alpha = 1.5f;
  return options;
}

// At rest the re-trace changes no bit; after a move and one round of the moving photons, every
// level's VPLs are those a fresh trace with the lights there leaves on the same levels.
TEST(VplHierarchy, MovingLightsFollowOnEveryLevel) {
  const Scene start = loadScene(movingCornell(0.0f));
  gi::MovingVpls vpls(start, hierarchyTrace(), 1u << 20, gpu::kMaxLights);
  ASSERT_GE(vpls.levels().size(), 3u);
  const std::vector<Light> before = vpls.vpls();
  for (const Light& l : test::litVpls(before)) ASSERT_GT(l.bandOuter, 0.0f);
  std::vector<Light> lights = before;
  vpls.moveTo(0.0f, lights, 0);
  for (size_t i = 0; i < before.size(); ++i)
    ASSERT_TRUE(lights[i].position == before[i].position && lights[i].intensity == before[i].intensity &&
                lights[i].range == before[i].range)
        << "a light at rest changed VPL " << i;

  const float later = 2.0f;
  vpls.moveTo(later, lights, 0);
  const gi::MovingVpls fresh(loadScene(movingCornell(later)), hierarchyTrace(), 1, gpu::kMaxLights,
                             vpls.levels());
  const std::vector<Light> a = test::litVpls(vpls.vpls()), b = test::litVpls(fresh.vpls());
  ASSERT_EQ(a.size(), b.size());
  size_t moved = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].bandOuter, b[i].bandOuter);
    EXPECT_LT(glm::distance(a[i].position, b[i].position), 1e-4f) << i;
    EXPECT_NEAR(a[i].intensity, b[i].intensity, 1e-5f * b[i].intensity + 1e-9f) << i;
  }
  for (size_t i = 0; i < before.size(); ++i) moved += vpls.vpls()[i].intensity != before[i].intensity;
  EXPECT_GT(moved, 0u) << "the moved lights changed no VPL";
  EXPECT_EQ(vpls.stats().droppedCells, 0u);
}

// ---- the command line ----

using test::CliTest;

TEST_F(CliTest, VplHierarchyOptions) {
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "tree"}), {"--vpl-hierarchy"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "grid", "--vpl-alpha", "0.1"}),
                 {"--vpl-alpha"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "grid", "--vpl-alpha", "nan"}),
                 {"--vpl-alpha"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "grid", "--vpl-count", "0"}),
                 {"--vpl-count 0"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "grid", "--vpl-range", "3"}),
                 {"--vpl-range"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-hierarchy", "grid", "--vpl-cutoff", "0.01"}),
                 {"--vpl-cutoff"});
  for (const std::vector<std::string>& good :
       {std::vector<std::string>{"--vpl-hierarchy", "grid", "--vpl-alpha", "2"},
        {"--vpl-hierarchy", "none", "--vpl-cutoff", "0.01", "--vpl-range", "3"}}) {
    std::vector<std::string> args = {"--gi", "vpl-only", "--photons", "4000", "--vpl-count", "256"};
    args.insert(args.end(), good.begin(), good.end());
    const test::CliResult ok = render("cornell", args);
    EXPECT_EQ(ok.exitCode, 0) << ok.output;
    EXPECT_TRUE(test::fs::exists(outPng()));
    test::fs::remove(outPng());
  }
}

}  // namespace
}  // namespace lll
