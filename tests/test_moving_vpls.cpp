// Instant radiosity that follows moving lights (gi/moving_vpls.h): lights at rest change no VPL,
// a budgeted re-trace ends where a fresh trace at the new positions starts, for any thread count,
// full slots are counted, the renderer uploads what moved, and the command line's options.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <optional>

#include "cli_test_support.h"
#include "core/errors.h"
#include "gi/moving_vpls.h"
#include "gi_test_support.h"
#include "renderer/renderer.h"
#include "scene/scene_source.h"
#include "shared/limits.h"
#include "test_support.h"

namespace lll {
namespace {

constexpr uint32_t kMaxSlots = gpu::kMaxLights;

// The Cornell room with three random lights that orbit (seed 5), placed where they are at `seconds`;
// with `gi` (vpl, vpl-only) the VPLs of 20,000 photons merged to 512 follow them.
SceneRequest movingCornellRequest(float seconds, GiMode gi = GiMode::None) {
  SceneRequest request{"cornell"};
  request.extraLights = 3;
  request.seed = 5;
  request.movingLights = true;
  request.time = seconds;
  request.gi.mode = gi;
  request.gi.photons = 20000;
  request.gi.vplCount = 512;
  return request;
}

Scene movingCornell(float seconds) {
  return loadScene(movingCornellRequest(seconds));
}

gi::VplOptions smallTrace(uint32_t threads = 0) {
  gi::VplOptions options;
  options.photons = 20000;
  options.vplCount = 512;
  options.seed = 5;
  options.threads = threads;
  return options;
}

bool sameLight(const Light& a, const Light& b) {
  return a.type == b.type && a.position == b.position && a.direction == b.direction && a.color == b.color &&
         a.intensity == b.intensity && a.range == b.range && a.nearDistance == b.nearDistance;
}

size_t countDifferent(const std::vector<Light>& a, const std::vector<Light>& b) {
  EXPECT_EQ(a.size(), b.size());
  size_t different = 0;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) different += !sameLight(a[i], b[i]);
  return different;
}

// Each of `got`'s lit VPLs against the one of `expected` at its place, relative to `scale` (metres)
// and to the brightest intensity.
void expectSameLitVpls(const std::vector<Light>& got, const std::vector<Light>& expected, float scale) {
  const std::vector<Light> a = test::litVpls(got), b = test::litVpls(expected);
  ASSERT_EQ(a.size(), b.size());
  float brightest = 0.0f;
  for (const Light& l : b) brightest = std::max(brightest, l.intensity);
  float worstPosition = 0.0f, worstIntensity = 0.0f, worstColor = 0.0f;
  for (size_t i = 0; i < a.size(); ++i) {
    worstPosition = std::max(worstPosition, glm::distance(a[i].position, b[i].position) / scale);
    worstIntensity = std::max(worstIntensity, std::abs(a[i].intensity - b[i].intensity) / brightest);
    worstColor = std::max(worstColor, glm::length(a[i].color - b[i].color));
  }
  EXPECT_LT(worstPosition, 1e-5f);
  EXPECT_LT(worstIntensity, 1e-5f);
  EXPECT_LT(worstColor, 1e-4f);
}

// Photons re-traced from lights that did not move land where they did: nothing changes, not even a
// rounding (no flicker). The scene they were traced in is gone by then.
TEST(MovingVpls, LightsAtRestChangeNothing) {
  std::optional<Scene> scene = movingCornell(0.0f);
  gi::MovingVpls vpls(*scene, smallTrace(), 1u << 20, kMaxSlots);
  scene.reset();  // the VPLs keep what they trace against (the bench's scenes are copies)
  ASSERT_GT(vpls.stats().movingPhotons, 100u);
  ASSERT_GT(vpls.stats().litSlots, 100u);
  const std::vector<Light> before = vpls.vpls();
  std::vector<Light> lights = before;
  for (int frame = 0; frame < 3; ++frame) {
    vpls.moveTo(0.0f, lights, 0);
    EXPECT_EQ(vpls.stats().retraced, vpls.stats().movingPhotons);
  }
  EXPECT_EQ(countDifferent(vpls.vpls(), before), 0u);
  EXPECT_EQ(countDifferent(lights, before), 0u);
}

// A light that moved: after one round of its photons (three frames of a third each), the VPLs are
// those a fresh trace with the lights there leaves on the same grid, and they did change.
TEST(MovingVpls, OneRoundOfTheBudgetEndsWhereAFreshTraceStarts) {
  const Scene start = movingCornell(0.0f);
  gi::MovingVpls probe(start, smallTrace(), 1, kMaxSlots);
  const uint64_t moving = probe.stats().movingPhotons;
  const uint32_t budget = uint32_t((moving + 2) / 3);
  gi::MovingVpls vpls(start, smallTrace(), budget, kMaxSlots);
  const std::vector<Light> before = vpls.vpls();
  std::vector<Light> lights(5, Light{});
  lights.insert(lights.end(), before.begin(), before.end());  // the block after five other lights
  const float later = 2.0f;
  for (int frame = 0; frame < 3; ++frame) {
    vpls.moveTo(later, lights, 5);
    EXPECT_EQ(vpls.stats().retraced, std::min<uint64_t>(budget, moving));
    if (frame == 0) {
      EXPECT_GT(countDifferent(vpls.vpls(), before), 0u) << "the first share moved nothing";
    }
  }
  EXPECT_EQ(countDifferent(std::vector<Light>(lights.begin() + 5, lights.end()), vpls.vpls()), 0u)
      << "the scene's lights should hold the block";
  const Scene end = movingCornell(later);
  const gi::MovingVpls fresh(end, smallTrace(), budget, kMaxSlots, vpls.levels());
  const Bounds bounds = end.worldBounds();
  expectSameLitVpls(vpls.vpls(), fresh.vpls(), glm::length(bounds.extent()));
  EXPECT_EQ(vpls.stats().droppedCells, 0u);
  std::printf("[ moving  ] %llu of 20000 photons leave the moving lights; %u VPLs lit of %u slots\n",
              (unsigned long long)moving, vpls.stats().litSlots, vpls.stats().slots);
}

TEST(MovingVpls, SameVplsWhateverTheThreads) {
  const Scene start = movingCornell(0.0f);
  gi::MovingVpls one(start, smallTrace(1), 300, kMaxSlots);
  gi::MovingVpls three(start, smallTrace(3), 300, kMaxSlots);
  std::vector<Light> a = one.vpls(), b = three.vpls();
  for (const float t : {0.5f, 1.0f}) {
    one.moveTo(t, a, 0);
    three.moveTo(t, b, 0);
  }
  EXPECT_EQ(countDifferent(one.vpls(), three.vpls()), 0u);
}

// With no room beyond the load's cells, the cells a moved light newly lights take the slots that
// emptied cells free, and the rest are counted as dropped.
TEST(MovingVpls, FullSlotsAreCountedNotOverrun) {
  const Scene start = movingCornell(0.0f);
  const gi::MovingVpls probe(start, smallTrace(), 1, kMaxSlots);
  const uint32_t lit = probe.stats().litSlots;
  gi::MovingVpls tight(start, smallTrace(), 1u << 20, lit, probe.levels());
  EXPECT_EQ(tight.stats().slots, lit);
  std::vector<Light> lights = tight.vpls();
  const float later = 7.0f;
  tight.moveTo(later, lights, 0);
  const gi::MovingVpls fresh(movingCornell(later), smallTrace(), 1, kMaxSlots, probe.levels());
  const uint32_t needed = fresh.stats().litSlots;
  EXPECT_EQ(tight.stats().litSlots, std::min(lit, needed));
  EXPECT_EQ(tight.stats().droppedCells, needed > lit ? needed - lit : 0u);
  EXPECT_EQ(lights.size(), lit);
  std::printf("[ moving  ] %u slots; %u cells lit after the move, %u dropped\n", lit, needed,
              tight.stats().droppedCells);
  EXPECT_THROW(gi::MovingVpls(start, smallTrace(), 1, lit - 1, probe.levels()), InputError);
}

// The bench moves its lights in a copy of a cached scene: the copy's VPLs move, the original's stay.
TEST(MovingVpls, ACopyOfTheSceneMovesOnItsOwn) {
  const Scene original = loadScene(movingCornellRequest(0.0f, GiMode::Vpl));
  ASSERT_TRUE(original.movingIndirect);
  Scene copy = original;
  ASSERT_TRUE(copy.movingIndirect);
  EXPECT_NE(copy.movingIndirect.vpls.get(), original.movingIndirect.vpls.get());
  copy.movingIndirect.vpls->moveTo(3.0f, copy.lights, copy.movingIndirect.first);
  EXPECT_GT(countDifferent(copy.lights, original.lights), 0u);
  const std::vector<Light> before = original.movingIndirect.vpls->vpls();
  Scene again = original;
  EXPECT_EQ(countDifferent(again.movingIndirect.vpls->vpls(), before), 0u);
  EXPECT_GT(countDifferent(copy.movingIndirect.vpls->vpls(), before), 0u);
}

// Through the renderer: after moveLightsTo the image is the one of a scene that simply holds the
// moved lights, and it is not the first frame's.
TEST(MovingVpls, TheRendererDrawsTheVplsThatMoved) {
  SceneRequest request = movingCornellRequest(0.0f, GiMode::VplOnly);
  request.gi.retrace = 1u << 20;
  Scene scene = loadScene(request);
  ASSERT_TRUE(scene.movingIndirect);
  EXPECT_TRUE(scene.lightAnimation.empty()) << "vpl-only: the moving lights themselves are gone";
  RenderSettings settings;
  settings.technique = "lll";
  settings.width = 96;
  settings.height = 72;
  settings.ambient = 0.0f;
  settings.exposure = 16.0f;
  Renderer renderer(test::gpuContext(), scene, settings);
  const test::Rendered first = test::render(renderer);
  renderer.moveLightsTo(scene, 3.0f);
  const test::Rendered moved = test::render(renderer);
  Scene still = scene;
  still.movingIndirect = {};
  const test::Rendered expected = test::render(still, settings);
  test::expectWithinBound(moved.ldr, expected.ldr, test::kSameImage, "moved VPLs");
  EXPECT_LT(test::psnr(moved.ldr, first.ldr), 60.0) << "the indirect light did not follow the lights";
  const auto stat = [&](const std::string& name) {
    for (const auto& [key, value] : moved.stats)
      if (key == name) return value;
    ADD_FAILURE() << name << " missing";
    return 0.0;
  };
  EXPECT_EQ(stat("vpl-retraced-photons"), stat("vpl-moving-photons"));
  EXPECT_GT(stat("vpl-lit-slots"), 100.0);
}

using test::CliTest;

TEST_F(CliTest, MovingGiOptions) {
  expectBadInput(render("cornell", {"--gi", "vpl", "--lights", "2", "--animate", "--vpl-count", "0"}),
                 {"--vpl-count 0", "--vpl-retrace 0"});
  expectBadInput(render("cornell", {"--gi", "vpl", "--vpl-retrace", "-1"}), {"--vpl-retrace"});
  const test::CliResult r = render(
      "cornell", {"--gi", "vpl-only", "--photons", "5000", "--lights", "2", "--animate", "--frames", "3"});
  EXPECT_EQ(r.exitCode, 0) << r;
  EXPECT_TRUE(std::filesystem::exists(outPng()));
}

}  // namespace
}  // namespace lll
