// The GPU particle system on lavapipe, validation on: the simulation against its own rules (same
// seed, same state; lifetimes, motion, floors), the GPU sort against a CPU sort of the read-back,
// and the images: a red light tints only the particles in its range, lll's smoke equals forward's,
// the translucent passes of the other techniques, and the soft fade at geometry.
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <set>

#include "particles/particle_system.h"
#include "scene/mesh_builder.h"
#include "scene/scene_source.h"
#include "test_presets_json.h"
#include "test_support.h"

namespace lll {
namespace {

using nlohmann::json;

constexpr float kPi = 3.14159265358979f;
// Steps of the smoke tests: 5 s, when the first puffs start to die.
constexpr uint32_t kSmokeSteps = 300;

// What a drawn frame left in the particle system, besides the images.
struct ParticleFrame {
  test::Rendered image;
  std::vector<gpu::Particle> particles;
  std::vector<glm::uvec2> order;
  gpu::ParticleCounters counters{};
  gpu::FrameUniforms uniforms{};
};

// Simulates `steps` fixed steps, the last in a drawn frame, as `lll render --frames steps` does;
// fails the test on any validation message.
ParticleFrame renderParticles(const Scene& scene, const RenderSettings& settings, uint32_t steps) {
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  ParticleFrame out;
  {
    Renderer renderer(context, scene, settings);
    renderer.advanceParticles(steps - 1);
    out.image.frame = renderer.renderFrame(true);
    out.image.hdr = renderer.hdrImage();
    out.image.ldr = renderer.ldrImage();
    out.image.stats = renderer.stats();
    out.uniforms = renderer.uniforms();
    if (ParticleSystem* particles = renderer.particles()) {
      out.particles = particles->readParticles();
      out.order = particles->readDrawOrder();
      out.counters = particles->readCounters();
    }
  }
  const auto messages = context.validationMessages();
  for (size_t i = before; i < messages.size(); ++i) ADD_FAILURE() << messages[i];
  return out;
}

// A preset curve at life fraction t, as shaders/particles/particle_data.glsl evaluates it.
float curveAt(const std::vector<float>& keys, float t) {
  if (keys.size() == 1) return keys[0];
  const float x = std::clamp(t, 0.0f, 1.0f) * float(keys.size() - 1);
  const size_t i = std::min(size_t(x), keys.size() - 2);
  return glm::mix(keys[i], keys[i + 1], x - float(i));
}

bool alive(const gpu::Particle& p) {
  return p.positionAge.w >= 0.0f && p.positionAge.w < p.velocityLifetime.w;
}

Material greyMaterial(const char* name, float grey) {
  Material m;
  m.name = name;
  m.baseColorFactor = glm::vec4(grey, grey, grey, 1.0f);
  m.metallic = 0.0f;
  m.roughness = 1.0f;
  return m;
}

// A quad of `size` facing +z, centred at `center`, of `material`.
void addWall(Scene& scene, uint32_t material, glm::vec3 center, glm::vec2 size) {
  MeshBuilder quad("wall");
  quad.setMaterial(material);
  quad.addQuad(glm::translate(glm::mat4(1.0f), center) * glm::rotate(glm::mat4(1.0f), kPi / 2, {1, 0, 0}),
               size);
  addInstance(scene, quad.addTo(scene));
}

Light pointLight(glm::vec3 position, glm::vec3 color, float intensity, float range) {
  Light l;
  l.position = position;
  l.color = color;
  l.intensity = intensity;
  l.range = range;
  return l;
}

// A grey wall 6 m behind the origin, seen from 6 m in front of it.
Scene wallScene() {
  Scene scene;
  scene.name = "particle-wall";
  scene.materials.push_back(greyMaterial("wall", 0.5f));
  addWall(scene, 0, {0, 0, -6}, {30, 30});
  scene.cameras.push_back(Camera{"front", {0, 0, 6}, {0, 0, 0}, {0, 1, 0}, glm::radians(60.0f)});
  return scene;
}

RenderSettings settingsFor(const std::string& technique, uint32_t width, uint32_t height) {
  RenderSettings s;
  s.technique = technique;
  s.width = width;
  s.height = height;
  return s;
}

// Pixel of world point `p` (row 0 at the top), and the view depth.
glm::vec3 project(const gpu::FrameUniforms& u, glm::vec3 p) {
  const glm::vec4 clip = u.viewProj * glm::vec4(p, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * u.viewport.x, (ndc.y * 0.5f + 0.5f) * u.viewport.y, clip.w};
}

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
  EXPECT_EQ(f.counters.draw, glm::uvec4(6, visible, 0, 0));
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

// --- Lighting ---------------------------------------------------------------------------------

struct LightingCase {
  const char* technique;
  const char* lighting;
};

void PrintTo(const LightingCase& c, std::ostream* os) {
  *os << c.technique << " " << c.lighting;
}

class ParticleLightingTest : public ::testing::TestWithParam<LightingCase> {};

// Still white puffs in a sphere of 3 m; a red light (range 2 m) among them at x = -1.5, a white
// light near the camera reaching all. Particles seen on their own (no other puff over them) are
// compared with and without the red light at their centre pixel.
TEST_P(ParticleLightingTest, RedLightTintsOnlyTheParticlesInItsRange) {
  const Light red = pointLight({-1.5f, 0, 0}, {1, 0, 0}, 4.0f, 2.0f);
  Scene withRed = wallScene();
  withRed.lights = {pointLight({0, 0, 4}, {1, 1, 1}, 20.0f, 15.0f), red};
  Scene withoutRed = withRed;
  withoutRed.lights.pop_back();
  RenderSettings settings = settingsFor(GetParam().technique, 160, 90);
  settings.particles = test::writePreset(test::stillPreset(), "still");
  settings.particleEmitter = "0,0,0";
  settings.particleLighting = GetParam().lighting;
  settings.ambient = 0.0f;
  const ParticleFrame lit = renderParticles(withRed, settings, 301);
  const ParticleFrame plain = renderParticles(withoutRed, settings, 301);
  ASSERT_EQ(lit.counters.dispatch.w, 64u);

  uint32_t inside = 0, outside = 0;
  float strongestTint = 0.0f;  // red over green of the reddest particle in range
  const float pixelsPerMetre = lit.uniforms.viewport.y / (2.0f * lit.uniforms.depthParams.w);
  for (uint32_t i = 0; i < lit.particles.size(); ++i) {
    const gpu::Particle& p = lit.particles[i];
    const glm::vec3 center = glm::vec3(p.positionAge);
    const glm::vec3 s = project(lit.uniforms, center);
    const float radius = 0.12f * pixelsPerMetre / s.z;
    bool alone = s.x > radius && s.y > radius && s.x < 160 - radius && s.y < 90 - radius;
    for (uint32_t j = 0; j < lit.particles.size() && alone; ++j) {
      const glm::vec3 o = project(lit.uniforms, glm::vec3(lit.particles[j].positionAge));
      alone = j == i || glm::length(glm::vec2(o - s)) > radius + 0.12f * pixelsPerMetre / o.z + 2.0f;
    }
    const float distance = glm::length(center - red.position);
    if (!alone || (distance > 0.75f * red.range && distance < 1.25f * red.range)) continue;
    const glm::vec4 a = lit.image.hdr.at(uint32_t(s.x), uint32_t(s.y));
    const glm::vec4 b = plain.image.hdr.at(uint32_t(s.x), uint32_t(s.y));
    if (distance <= 0.75f * red.range) {
      ++inside;
      EXPECT_GT(a.r, 1.05f * b.r) << "particle " << i << " in the red light's range gained no red";
      EXPECT_NEAR(a.g, b.g, 0.01f * b.g + 1e-4f) << "particle " << i;
      EXPECT_GT(a.r, 1.05f * a.g) << "particle " << i << " is not red-tinted";
      strongestTint = std::max(strongestTint, a.r / a.g);
    } else {
      ++outside;
      EXPECT_EQ(a, b) << "particle " << i << " outside the red light's range changed";
      EXPECT_NEAR(a.r, a.g, 0.02f * a.g) << "particle " << i << " outside the red light's range is tinted";
      EXPECT_GT(a.g, 0.05f) << "particle " << i << " is not lit by the white light";
    }
  }
  EXPECT_GE(inside, 2u);
  EXPECT_GE(outside, 5u);
  EXPECT_GT(strongestTint, 1.5f);
}

INSTANTIATE_TEST_SUITE_P(TechniquesAndLightings, ParticleLightingTest,
                         ::testing::Values(LightingCase{"forward", "pixel"},
                                           LightingCase{"forward", "vertex"}, LightingCase{"lll", "pixel"},
                                           LightingCase{"lll", "vertex"}),
                         [](const auto& info) {
                           return std::string(info.param.technique) + "_" + info.param.lighting;
                         });

// The default scene's smoke plume 5 s after it started (its puffs live 5 to 8 s), 1,024 particles,
// small enough for lavapipe.
ParticleFrame smokeFrame(const std::string& technique, const std::string& lighting) {
  static const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings = settingsFor(technique, 128, 72);
  settings.particles = "smoke";
  settings.particleCount = 1024;
  settings.particleLighting = lighting;
  return renderParticles(scene, settings, kSmokeSteps);
}

class SmokeMatchesForward : public ::testing::TestWithParam<const char*> {};

TEST_P(SmokeMatchesForward, InLll) {
  const ParticleFrame forward = smokeFrame("forward", GetParam());
  const ParticleFrame lll = smokeFrame("lll", GetParam());
  EXPECT_GT(forward.counters.dispatch.w, 600u);  // 1024 / 8 spawns a second for 5 s: 640
  const double psnr = test::psnr(lll.image.ldr, forward.image.ldr);
  RecordProperty("psnr", std::to_string(psnr));
  EXPECT_GE(psnr, 40.0);
  // The smoke is really in the picture: forward without it differs.
  RenderSettings clear = settingsFor("forward", 128, 72);
  const test::Rendered noSmoke = test::render(loadScene(SceneRequest{"atrium", 0, 1}), clear);
  EXPECT_LT(test::psnr(noSmoke.ldr, forward.image.ldr), 30.0);
}

INSTANTIATE_TEST_SUITE_P(Lightings, SmokeMatchesForward, ::testing::Values("pixel", "vertex"),
                         [](const auto& info) { return std::string(info.param); });

double totalLuminance(const HdrImage& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    sum += 0.2126 * image.rgba[i] + 0.7152 * image.rgba[i + 1] + 0.0722 * image.rgba[i + 2];
  return sum;
}

TEST(SmokeInOtherTechniques, DeferredAndPrepassLightItForwardDeferredUnlitLeavesItDark) {
  const ParticleFrame forward = smokeFrame("forward", "pixel");
  const ParticleFrame deferred = smokeFrame("deferred", "pixel");
  const ParticleFrame prepass = smokeFrame("prepass", "pixel");
  EXPECT_GE(test::psnr(deferred.image.ldr, forward.image.ldr), 40.0);
  EXPECT_GE(test::psnr(prepass.image.ldr, forward.image.ldr), 35.0);  // prepass's own bar (test_deferred)
  static const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings = settingsFor("deferred", 128, 72);
  settings.particles = "smoke";
  settings.particleCount = 1024;
  settings.deferredTranslucent = "unlit";
  const ParticleFrame unlit = renderParticles(scene, settings, kSmokeSteps);
  // Unlit smoke covers the lit scene with grey-black (the seeds' Figure 1.1).
  EXPECT_LT(totalLuminance(unlit.image.hdr), 0.9 * totalLuminance(forward.image.hdr));
}

// --- Soft fade --------------------------------------------------------------------------------

// One big still puff 10 cm in front of the wall: with a 1 m fade it almost vanishes into the wall,
// with a 1 cm fade it shows at full strength.
TEST(SoftParticles, FadeWhereTheyMeetTheWall) {
  Scene scene = wallScene();
  scene.lights = {pointLight({0, 0, 2}, {1, 1, 1}, 60.0f, 20.0f)};
  json preset = test::stillPreset();
  preset["count"] = 1;
  preset["emitter"] = {{"shape", "point"}, {"radius", 0}, {"offset", {0, 0, 0}}};
  preset["size"] = {1.0};
  RenderSettings settings = settingsFor("forward", 96, 54);
  settings.particleEmitter = "0,0,-5.9";
  const test::Rendered wall = test::render(scene, settings);
  float contrast[2];
  for (int i = 0; i < 2; ++i) {
    preset["softness"] = i == 0 ? 0.01 : 1.0;
    settings.particles = test::writePreset(preset, "soft");
    const ParticleFrame f = renderParticles(scene, settings, 2);
    ASSERT_EQ(f.counters.dispatch.w, 1u);
    contrast[i] = std::abs(f.image.hdr.at(48, 27).g - wall.hdr.at(48, 27).g);
  }
  EXPECT_GT(contrast[0], 0.05f);
  EXPECT_NEAR(contrast[1], 0.1f * contrast[0], 0.03f * contrast[0]);  // 10 cm of a 1 m fade
}

// --- Glass ------------------------------------------------------------------------------------

// A grey wall at z = 0 and a 2 m pane of glass 1 m in front of it, seen from z = 5. Light A, in
// front of the glass, reaches the glass but not the wall; light D lights the wall beside the
// glass; light B sits behind the wall, its range reaching through the wall past the glass.
Scene glassScene(bool lightBehind, bool lightInFront) {
  Scene scene;
  scene.name = "glass-wall";
  scene.materials.push_back(greyMaterial("wall", 0.6f));
  Material glass = greyMaterial("glass", 0.9f);
  glass.baseColorFactor.a = 0.4f;
  glass.roughness = 0.3f;
  glass.alphaMode = AlphaMode::Blend;
  scene.materials.push_back(glass);
  addWall(scene, 0, {0, 0, 0}, {20, 20});
  addWall(scene, 1, {0, 0, 1}, {2, 2});
  scene.cameras.push_back(Camera{"front", {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, glm::radians(60.0f)});
  scene.lights.push_back(pointLight({2.5f, 0, 0.3f}, {1, 1, 1}, 2.0f, 1.0f));
  if (lightInFront) scene.lights.push_back(pointLight({0, 0, 1.6f}, {1, 1, 1}, 3.0f, 1.2f));
  if (lightBehind) scene.lights.push_back(pointLight({0, 0, -0.5f}, {0, 1, 0}, 20.0f, 2.0f));
  return scene;
}

glm::vec3 meanColor(const HdrImage& image, uint32_t x0, uint32_t y0, uint32_t size) {
  glm::vec3 sum(0.0f);
  for (uint32_t y = y0; y < y0 + size; ++y)
    for (uint32_t x = x0; x < x0 + size; ++x) sum += glm::vec3(image.at(x, y));
  return sum / float(size * size);
}

TEST(Glass, LitByTheLightInFrontOfItNotByTheOneBehindTheWall) {
  const RenderSettings settings = settingsFor("lll", 160, 90);
  const test::Rendered front = test::render(glassScene(false, true), settings);
  const test::Rendered both = test::render(glassScene(true, true), settings);
  const test::Rendered neither = test::render(glassScene(false, false), settings);
  // The glass covers the middle of the image; D lights the wall around x = 2.5 m.
  const glm::vec3 glassLit = meanColor(front.hdr, 76, 41, 8), glassUnlit = meanColor(neither.hdr, 76, 41, 8);
  EXPECT_GT(glassLit.g, 1.5f * glassUnlit.g) << "the glass took no light from the light in front of it";
  const glm::vec3 wallBesideGlass = meanColor(front.hdr, 117, 43, 4), wallFar = meanColor(front.hdr, 2, 2, 4);
  EXPECT_GT(wallBesideGlass.g, 3.0f * wallFar.g) << "the wall is not lit";
  // The light behind the wall changes no pixel in front of it, on the glass or anywhere else.
  EXPECT_EQ(test::psnr(both.ldr, front.ldr), INFINITY);
  EXPECT_EQ(meanColor(both.hdr, 76, 41, 8), glassLit);
  // And lll gives forward's image.
  const test::Rendered reference = test::render(glassScene(true, true), settingsFor("forward", 160, 90));
  EXPECT_GE(test::psnr(both.ldr, reference.ldr), 45.0);
}

}  // namespace
}  // namespace lll
