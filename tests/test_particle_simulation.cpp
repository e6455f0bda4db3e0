// The particle simulation and sort on lavapipe, validation on: same seed, same state; drawn frames
// and silent steps agree; lifetimes, straight flight without forces, floors; the bitonic sort
// against std::sort, and the frame's draw order against a CPU sort of its read-back.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <set>

#include "particle_test_support.h"
#include "scene/scene_source.h"
#include "test_presets_json.h"

namespace lll {
namespace {

using nlohmann::json;
using namespace test;

// --- Simulation -------------------------------------------------------------------------------

std::vector<gpu::Particle> simulate(const ParticleSystemOptions& options, uint32_t steps) {
  Context& context = test::gpuContext();
  ParticleSystem system(context, options);
  context.submitAndWait([&](VkCommandBuffer cmd) { system.recordSteps(cmd, steps); });
  EXPECT_EQ(system.steps(), steps);
  return system.readParticles();
}

ParticleSystemOptions smokeOptions(uint32_t count, uint32_t seed) {
  ParticleSystemOptions options;
  options.preset = loadParticlePreset("smoke");
  options.count = count;
  options.seed = seed;
  return options;
}

TEST(ParticleSimulation, SameSeedSameStateDifferentSeedDifferentState) {
  const auto a = simulate(smokeOptions(2000, 7), 120);
  const auto b = simulate(smokeOptions(2000, 7), 120);
  const auto c = simulate(smokeOptions(2000, 8), 120);
  ASSERT_EQ(a.size(), 2000u);
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(gpu::Particle)), 0);
  size_t aliveCount = 0, differing = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    aliveCount += alive(a[i]);
    differing += alive(a[i]) && std::memcmp(&a[i], &c[i], sizeof(gpu::Particle)) != 0;
  }
  EXPECT_GT(aliveCount, 400u);
  EXPECT_EQ(differing, aliveCount) << "every particle depends on the seed";
}

TEST(ParticleSimulation, DrawnFramesAndSilentStepsReachTheSameState) {
  const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings = settingsFor("forward", 32, 18);
  settings.particles = "smoke";
  settings.particleCount = 500;
  Context& context = test::gpuContext();
  Renderer silent(context, scene, settings), drawn(context, scene, settings);
  silent.advanceParticles(39);
  silent.renderFrame(false);
  for (int i = 0; i < 40; ++i) drawn.renderFrame(false);
  ASSERT_EQ(silent.particles()->steps(), 40u);
  ASSERT_EQ(drawn.particles()->steps(), 40u);
  const auto a = silent.particles()->readParticles(), b = drawn.particles()->readParticles();
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(gpu::Particle)), 0);
}

ParticleSystemOptions optionsFrom(const json& preset) {
  ParticleSystemOptions options;
  options.preset = parseParticlePreset(preset.dump(), "test");
  return options;
}

TEST(ParticleSimulation, ParticlesLiveTheirLifetimeAndFlyStraightWithoutForces) {
  json preset = test::stillPreset();
  preset["count"] = 200;
  preset["lifetime"] = {1.0, 2.0};
  preset["emitter"]["shape"] = "point";
  preset["velocity"]["spread"] = 180;
  preset["velocity"]["speed"] = {1.0, 2.0};
  const auto particles = simulate(optionsFrom(preset), 300);
  uint32_t aliveCount = 0;
  for (const gpu::Particle& p : particles) {
    if (!alive(p)) continue;
    ++aliveCount;
    const float lifetime = p.velocityLifetime.w, age = p.positionAge.w,
                speed = glm::length(glm::vec3(p.velocityLifetime));
    EXPECT_TRUE(lifetime >= 1.0f && lifetime <= 2.0f) << lifetime;
    EXPECT_TRUE(speed >= 1.0f - 1e-4f && speed <= 2.0f + 1e-4f) << speed;
    // Born at the emitter, flying straight at its launch speed for `age` seconds.
    EXPECT_NEAR(glm::length(glm::vec3(p.positionAge)), speed * age, 1e-3f * (1.0f + speed * age));
  }
  // 100 spawns a second (count / max lifetime), each living 1.5 s on average: about 150 alive.
  EXPECT_GT(aliveCount, 125u);
  EXPECT_LT(aliveCount, 175u);
}

TEST(ParticleSimulation, FloorsKillOrBounceWhatFallsOnThem) {
  json preset = test::stillPreset();
  preset["count"] = 300;
  preset["lifetime"] = {3.0, 3.0};
  preset["emitter"]["shape"] = "point";
  preset["velocity"]["spread"] = 40;
  preset["velocity"]["speed"] = {2.0, 4.0};
  preset["gravity"] = {0, -9.81, 0};
  uint32_t aliveByMode[2] = {0, 0};
  for (int bounce = 0; bounce < 2; ++bounce) {
    preset["floor"] = {{"mode", bounce ? "bounce" : "kill"}, {"restitution", 0.5}};
    ParticleSystemOptions options = optionsFrom(preset);
    options.source = glm::vec3(0.0f, 1.0f, 0.0f);  // the floor is the plane y = 1
    for (const gpu::Particle& p : simulate(options, 240)) {
      if (!alive(p)) continue;
      ++aliveByMode[bounce];
      EXPECT_GE(p.positionAge.y, 1.0f - 1e-3f) << (bounce ? "bounce" : "kill");
    }
  }
  // Launched at up to 4 m/s, a particle is back on the floor within 0.82 s of its 3 s life.
  EXPECT_LT(aliveByMode[0], 100u);
  EXPECT_GE(aliveByMode[1], 295u);  // every slot in use: bouncing particles live their 3 s
}

// --- Sort -------------------------------------------------------------------------------------

TEST(BitonicSort, MatchesStdSortWithTies) {
  Context& context = test::gpuContext();
  std::mt19937 rng(5);
  for (const uint32_t count : {1u, 5u, 1000u, 1024u, 1025u, 4096u, 70000u, gpu::kMaxParticles}) {
    BitonicSort sorter(context, count);
    const uint32_t n = sorter.paddedCount();
    ASSERT_GE(n, count);
    ASSERT_EQ(n & (n - 1), 0u);
    std::vector<glm::uvec2> pairs(n);
    for (glm::uvec2& p : pairs) p = {rng() % 97u, rng() % 13u};  // many equal keys, some equal pairs
    Buffer buffer(context, n * sizeof(glm::uvec2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload);
    buffer.upload(std::span<const glm::uvec2>(pairs));
    context.submitAndWait([&](VkCommandBuffer cmd) {
      sorter.record(cmd, buffer);
      memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    });
    std::vector<glm::uvec2> sorted(n);
    std::memcpy(sorted.data(), buffer.mapped(), n * sizeof(glm::uvec2));
    std::sort(pairs.begin(), pairs.end(),
              [](glm::uvec2 a, glm::uvec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    EXPECT_TRUE(sorted == pairs) << count << " pairs";
  }
  EXPECT_TRUE(context.validationMessages().empty());
}

TEST(ParticleSort, GpuDrawOrderIsTheCpuSortOfTheReadBack) {
  const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings = settingsFor("forward", 64, 36);
  settings.particles = "smoke";
  settings.particleCount = 3000;  // not a power of two: the sort array has padding
  const ParticleFrame f = renderParticles(scene, settings, kSmokeSteps);
  const gpu::FrameUniforms& u = f.uniforms;
  auto depthOf = [&](uint32_t slot) {
    return -(u.view * glm::vec4(glm::vec3(f.particles[slot].positionAge), 1)).z;
  };
  // The CPU's frustum test, as shaders/particles/sort_keys.comp makes it, with a margin either
  // side: particles on the boundary may go either way in float arithmetic.
  const ParticlePreset smoke = loadParticlePreset("smoke");
  auto frustumDistance = [&](const gpu::Particle& p) {
    const glm::vec3 view = glm::vec3(u.view * glm::vec4(glm::vec3(p.positionAge), 1.0f));
    const float depth = -view.z,
                radius = curveAt(smoke.size, p.positionAge.w / p.velocityLifetime.w) * p.attributes.x;
    const glm::vec2 tanHalf(u.depthParams.z, u.depthParams.w);
    const glm::vec2 side =
        (glm::abs(glm::vec2(view)) - depth * tanHalf) / glm::sqrt(1.0f + tanHalf * tanHalf);
    return std::max({u.depthParams.x - depth, depth - u.depthParams.y, side.x, side.y}) - radius;
  };
  uint32_t aliveCount = 0, surelyInside = 0, surelyOutside = 0;
  for (const gpu::Particle& p : f.particles) {
    if (!alive(p)) continue;
    ++aliveCount;
    surelyInside += frustumDistance(p) < -1e-3f;
    surelyOutside += frustumDistance(p) > 1e-3f;
  }
  const uint32_t visible = f.counters.dispatch.w;
  EXPECT_EQ(f.counters.alive.x, aliveCount);
  EXPECT_EQ(f.counters.draw, glm::uvec4(6 * visible, 1, 0, 0));
  EXPECT_GT(visible, 1500u);
  EXPECT_GE(visible, surelyInside);
  EXPECT_LE(visible, aliveCount - surelyOutside);

  // Sorting the read-back on the CPU changes nothing, and it holds every slot once.
  std::vector<glm::uvec2> cpuSorted = f.order;
  std::sort(cpuSorted.begin(), cpuSorted.end(),
            [](glm::uvec2 a, glm::uvec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  EXPECT_TRUE(cpuSorted == f.order);
  std::set<uint32_t> slots;
  for (const glm::uvec2& pair : f.order) slots.insert(pair.y);
  EXPECT_EQ(slots.size(), f.order.size());
  EXPECT_EQ(*slots.rbegin(), f.order.size() - 1);

  // Visible particles first, back to front by the depth the CPU computes from the read-back.
  float previous = INFINITY;
  for (uint32_t i = 0; i < f.order.size(); ++i) {
    const glm::uvec2 pair = f.order[i];
    if (i >= visible) {
      EXPECT_EQ(pair.x, gpu::kParticleHiddenKey);
      continue;
    }
    ASSERT_LT(pair.y, f.particles.size());
    ASSERT_TRUE(alive(f.particles[pair.y]));
    EXPECT_LT(frustumDistance(f.particles[pair.y]), 1e-3f)
        << "slot " << pair.y << " is drawn but out of view";
    const float depth = depthOf(pair.y);
    EXPECT_NEAR(std::bit_cast<float>(~pair.x), depth, 1e-4f * depth);
    EXPECT_LE(depth, previous + 1e-4f * depth) << "at " << i;
    previous = depth;
  }
}

}  // namespace
}  // namespace lll
