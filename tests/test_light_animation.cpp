// Moving lights (scene/light_animation.h): the motion's geometry, its determinism, the scene
// loaded at a time, and in images a renderer whose lights moved between frames against one made for
// that time (every technique must rebuild its light data from the moved lights: the lists, the
// deferred light volumes placed on the CPU, the local shadows written into the light array).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "cli_test_support.h"
#include "core/errors.h"
#include "image_bound.h"
#include "render/image_io.h"
#include "renderer/renderer.h"
#include "scene/light_animation.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

SceneRequest movingRequest(uint32_t lights, float seconds) {
  SceneRequest request{"atrium", lights, 7};
  request.movingLights = true;
  request.time = seconds;
  return request;
}

// The image tests' frame: 96x54, `technique`, `shadows` (sun | all | none; 4 shadowed lights).
RenderSettings movingSettings(const std::string& technique, ShadowMode shadows) {
  RenderSettings settings;
  settings.width = 96;
  settings.height = 54;
  settings.technique = technique;
  settings.shadows = shadows;
  settings.shadowLights = 4;
  return settings;
}

float horizontalDistance(glm::vec3 a, glm::vec3 b) {
  return std::hypot(a.x - b.x, a.z - b.z);
}

// Orbit and bob, checked against the closed form's geometry: at time 0 each light stands where it
// was scattered; later it is on its circle (radius r about the centre, in the horizontal plane),
// within its bob of the centre's height, one orbit later back where it was, and it moves at r |w|
// along the circle.
TEST(LightAnimation, LightsOrbitAndBobFromWhereTheyWereScattered) {
  const Scene still = loadScene(SceneRequest{"atrium", 64, 7});
  const Scene moving = loadScene(movingRequest(64, 0.0f));
  const LightAnimation& animation = moving.lightAnimation;
  ASSERT_EQ(animation.motions.size(), 64u);
  ASSERT_EQ(animation.first + 64u, moving.lights.size()) << "the --lights lights are the last ones";
  const float diagonal = glm::length(moving.worldBounds().extent());
  for (uint32_t i = 0; i < moving.lights.size(); ++i)
    EXPECT_EQ(moving.lights[i].position, still.lights[i].position) << "light " << i << " at time 0";
  for (const LightMotion& m : animation.motions) {
    EXPECT_GE(m.radius, 0.01f * diagonal * 0.999f);
    EXPECT_LE(m.radius, 0.04f * diagonal * 1.001f);
    EXPECT_GE(std::abs(m.angularSpeed), 0.25f * 0.999f);
    EXPECT_LE(std::abs(m.angularSpeed), 1.0f * 1.001f);
    for (const float t : {0.7f, 3.1f, 250.0f}) {
      const glm::vec3 p = positionAt(m, t);
      EXPECT_NEAR(horizontalDistance(p, orbitCenter(m)), m.radius, 1e-4f * diagonal) << "t " << t;
      EXPECT_LE(std::abs(p.y - orbitCenter(m).y), m.bobAmplitude * 1.0001f + 1e-5f) << "t " << t;
      const float period = 6.2831853f / std::abs(m.angularSpeed);
      const glm::vec3 later = positionAt(m, t + period);
      EXPECT_NEAR(horizontalDistance(p, later), 0.0f, 1e-3f * m.radius) << "one orbit later, t " << t;
      const float dt = 1e-3f;
      const float step = horizontalDistance(positionAt(m, t + dt), positionAt(m, t - dt)) / (2.0f * dt);
      EXPECT_NEAR(step, m.radius * std::abs(m.angularSpeed), 0.01f * m.radius * std::abs(m.angularSpeed))
          << "speed along the orbit, t " << t;
    }
  }
}

// The same seed and time give the same lights; a light's motion does not depend on how many
// lights there are; another seed or time moves them elsewhere.
TEST(LightAnimation, DeterministicForASeedAndATime) {
  const Scene a = loadScene(movingRequest(32, 4.25f));
  const Scene b = loadScene(movingRequest(32, 4.25f));
  for (size_t i = 0; i < a.lights.size(); ++i) EXPECT_EQ(a.lights[i].position, b.lights[i].position);
  const Scene still = loadScene(SceneRequest{"atrium", 32, 7});
  size_t moved = 0;
  for (size_t i = a.lightAnimation.first; i < a.lights.size(); ++i)
    moved += glm::length(a.lights[i].position - still.lights[i].position) > 1e-3f;
  EXPECT_EQ(moved, 32u) << "every random light moved by 4.25 s";
  for (size_t i = 0; i < a.lightAnimation.first; ++i)
    EXPECT_EQ(a.lights[i].position, still.lights[i].position) << "the scene's own lights stay";

  const Bounds bounds = still.worldBounds();
  const uint32_t first = a.lightAnimation.first;
  const LightAnimation few = makeLightAnimation(still.lights, first, 8, bounds, 7);
  const LightAnimation all = makeLightAnimation(still.lights, first, 32, bounds, 7);
  const LightAnimation other = makeLightAnimation(still.lights, first, 8, bounds, 8);
  for (size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(positionAt(few.motions[i], 9.0f), positionAt(all.motions[i], 9.0f)) << "light " << i;
    EXPECT_GT(glm::length(positionAt(few.motions[i], 9.0f) - positionAt(other.motions[i], 9.0f)), 1e-3f)
        << "another seed, light " << i;
  }
}

TEST(LightAnimation, RejectsTimesOutsideTheRange) {
  for (const float t : {-1.0f, std::numeric_limits<float>::quiet_NaN(),
                        std::numeric_limits<float>::infinity(), kMaxAnimationSeconds * 2.0f}) {
    try {
      loadScene(movingRequest(4, t));
      ADD_FAILURE() << "time " << t << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--time"), std::string::npos) << e.what();
    }
  }
}

// A renderer whose lights moved between frames draws what a renderer made at that time draws: for
// the light lists (lll, tiled), the light volumes placed on the CPU each frame (deferred), and lll
// with local shadows, whose views live in the light array that the move writes again. The moved
// image must also differ from the first one, or the test would prove nothing.
TEST(LightAnimation, LightsMovedBetweenFramesDrawWhatTheirTimeDraws) {
  struct Case {
    std::string technique;
    ShadowMode shadows;
  };
  for (const Case& c : {Case{"lll", ShadowMode::None}, Case{"tiled", ShadowMode::None},
                        Case{"deferred", ShadowMode::None}, Case{"lll", ShadowMode::All}}) {
    SCOPED_TRACE(fmt::format("{} shadows {}", c.technique, c.shadows));
    const RenderSettings settings = movingSettings(c.technique, c.shadows);
    Scene scene = loadScene(movingRequest(48, 0.0f));
    Renderer renderer(test::gpuContext(), scene, settings);
    const test::Rendered first = test::render(renderer);
    placeLightsAt(scene.lights, scene.lightAnimation, 6.0f);
    renderer.updateLights();
    const test::Rendered moved = test::render(renderer);

    const Scene atSix = loadScene(movingRequest(48, 6.0f));
    const test::Rendered fresh = test::render(atSix, settings);
    test::expectWithinBound(moved.ldr, fresh.ldr, test::kSameImage, "moved vs made at 6 s, " + c.technique);
    EXPECT_LT(test::psnr(moved.ldr, first.ldr), 40.0) << "the lights' move changed the image";
  }
}

// Where nothing reads the lights' positions on the CPU (--light-motion auto), moveLightsTo leaves the
// scene's lights as they are and the next frame's first pass places them on the GPU: the image of a
// renderer made at that time, for every technique that reads lights on the GPU only. Where the CPU
// reads them (deferred's and the pre-pass's volumes, local shadows' views) they are placed in the
// scene and uploaded, as before. After a GPU move, updateLights draws the scene's lights as they
// are on the CPU again.
TEST(LightAnimation, MovedOnTheGpuWhereTheCpuDoesNotReadThem) {
  struct Case {
    std::string technique;
    ShadowMode shadows;
    bool onGpu;
  };
  const Scene atThree = loadScene(movingRequest(48, 3.0f)), atSix = loadScene(movingRequest(48, 6.0f));
  for (const Case& c : {Case{"forward", ShadowMode::Sun, true}, Case{"lll", ShadowMode::None, true},
                        Case{"tiled", ShadowMode::Sun, true}, Case{"clustered", ShadowMode::None, true},
                        Case{"deferred", ShadowMode::None, false}, Case{"prepass", ShadowMode::Sun, false},
                        Case{"lll", ShadowMode::All, false}}) {
    SCOPED_TRACE(fmt::format("{} shadows {}", c.technique, c.shadows));
    const RenderSettings settings = movingSettings(c.technique, c.shadows);
    Scene scene = loadScene(movingRequest(48, 0.0f));
    const std::vector<Light> atZero = scene.lights;
    Renderer renderer(test::gpuContext(), scene, settings);
    EXPECT_EQ(renderer.lightsMoveOnGpu(), c.onGpu);
    const test::Rendered first = test::render(renderer);
    renderer.moveLightsTo(scene, 6.0f);
    const test::Rendered moved = test::render(renderer);
    test::expectWithinBound(moved.ldr, test::render(atSix, settings).ldr, test::kSameImage,
                            "moved to 6 s vs made at 6 s, " + c.technique);
    EXPECT_LT(test::psnr(moved.ldr, first.ldr), 40.0) << "the lights' move changed the image";
    size_t unchanged = 0;
    for (size_t i = 0; i < scene.lights.size(); ++i)
      unchanged += scene.lights[i].position == atZero[i].position;
    EXPECT_EQ(unchanged == scene.lights.size(), c.onGpu) << "the scene's lights stay where they were";
    if (!c.onGpu) continue;
    const size_t passes = std::count_if(moved.frame.passes.begin(), moved.frame.passes.end(),
                                        [](const PassTime& p) { return p.name == "lights-move"; });
    EXPECT_EQ(passes, 1u);
    placeLightsAt(scene.lights, scene.lightAnimation, 3.0f);
    renderer.updateLights();
    test::expectWithinBound(test::render(renderer).ldr, test::render(atThree, settings).ldr, test::kSameImage,
                            "placed at 3 s on the CPU after a GPU move, " + c.technique);
  }
}

// --light-motion gpu is refused where the CPU reads the lights' positions, and cpu keeps them there.
TEST(LightAnimation, LightMotionSetting) {
  Scene scene = loadScene(movingRequest(8, 0.0f));
  RenderSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.lightMotion = LightPlacement::Gpu;
  for (const char* technique : {"deferred", "prepass"}) {
    settings.technique = technique;
    EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError) << technique;
  }
  settings.technique = "lll";
  settings.shadows = ShadowMode::All;
  EXPECT_THROW(Renderer(test::gpuContext(), scene, settings), InputError);
  settings.shadows = ShadowMode::None;
  EXPECT_TRUE(Renderer(test::gpuContext(), scene, settings).lightsMoveOnGpu());
  settings.lightMotion = LightPlacement::Cpu;
  EXPECT_FALSE(Renderer(test::gpuContext(), scene, settings).lightsMoveOnGpu());
}

// The GPU places every light where positionAt (the CPU, in double precision) does, at any time up
// to a day, to within a hundred-thousandth of the orbit's radius: the orbit reaches 13,750 turns
// there, where one rounding of a 32-bit product of speed and time moves a light by a few
// thousandths of its radius (shaders/lighting/move_lights.comp splits both so that it is exact).
TEST(LightAnimation, GpuPositionsAreTheCpusUpToADay) {
  Scene scene = loadScene(movingRequest(256, 0.0f));
  RenderSettings settings;
  settings.width = 16;
  settings.height = 16;
  settings.technique = "forward";
  Renderer renderer(test::gpuContext(), scene, settings);
  ASSERT_TRUE(renderer.lightsMoveOnGpu());
  const LightAnimation& animation = scene.lightAnimation;
  for (const float t : {0.0f, 6.0f, 1234.567f, 86399.98f}) {
    renderer.moveLightsTo(scene, t);
    renderer.renderFrame(false);
    const std::vector<uint8_t> bytes = readBack(test::gpuContext(), renderer.gpuScene().lightBuffer(),
                                                scene.lights.size() * sizeof(gpu::GpuLight));
    float worst = 0.0f;
    for (size_t i = 0; i < animation.motions.size(); ++i) {
      gpu::GpuLight light;
      std::memcpy(&light, bytes.data() + (animation.first + i) * sizeof(gpu::GpuLight), sizeof(light));
      const LightMotion& m = animation.motions[i];
      const float error = glm::length(glm::vec3(light.positionRange) - positionAt(m, t)) / m.radius;
      worst = std::max(worst, error);
      EXPECT_EQ(light.positionRange.w, scene.lights[animation.first + i].range) << "only the position moves";
    }
    EXPECT_LT(worst, 1e-5f) << "at " << t << " s";
    std::printf("GPU against CPU positions at %.2f s: at most %.2e of the orbit's radius\n", t, worst);
  }
}

// `lll render --animate --frames 31 --time 1` moves the lights 1/60 s a frame and draws the last at
// 1.5 s: the image of `--time 1.5` (the command line's per-frame path, with lll's lists).
class LightAnimationCli : public test::CliTest {};

TEST_F(LightAnimationCli, AnimatedFramesEndWhereTheirTimeIs) {
  auto run = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = {"render",      "atrium", "--width",  "96", "--height", "54",
                                     "--technique", "lll",    "--lights", "24", "--seed",   "5"};
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runLll(args);
  };
  const std::filesystem::path animated = dir_ / "animated.png", atTime = dir_ / "at-time.png",
                              start = dir_ / "start.png";
  test::CliResult r = run({"--animate", "--frames", "31", "--time", "1", "--out", animated.string()});
  ASSERT_EQ(r.exitCode, 0) << r;
  r = run({"--time", "1.5", "--out", atTime.string()});
  ASSERT_EQ(r.exitCode, 0) << r;
  r = run({"--time", "1", "--out", start.string()});
  ASSERT_EQ(r.exitCode, 0) << r;
  test::expectWithinBound(readPng(animated), readPng(atTime), test::kSameImage,
                          "--animate to 1.5 s vs --time 1.5");
  EXPECT_LT(test::psnr(readPng(animated), readPng(start)), 60.0)
      << "half a second of motion changed the image";
}

}  // namespace
}  // namespace lll
