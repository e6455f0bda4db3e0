// Particle and glass images on lavapipe, validation on: a red light tints only the particles in its
// range, lll's smoke equals forward's, the other techniques' translucent passes, the soft fade
// at geometry, and glass lit by the light in front of it at its own depth.
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

// --- Lighting ---------------------------------------------------------------------------------

struct LightingCase {
  const char* technique;
  ParticleLighting lighting;
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
                         ::testing::Values(LightingCase{"forward", ParticleLighting::Pixel},
                                           LightingCase{"forward", ParticleLighting::Vertex},
                                           LightingCase{"lll", ParticleLighting::Pixel},
                                           LightingCase{"lll", ParticleLighting::Vertex},
                                           LightingCase{"lll", ParticleLighting::Atlas}),
                         [](const auto& info) {
                           return fmt::format("{}_{}", info.param.technique, info.param.lighting);
                         });

// The default scene's smoke plume 5 s after it started (its puffs live 5 to 8 s), 1,024 particles,
// small enough for lavapipe. Forward is the reference: on the geometry (test::reference).
ParticleFrame smokeFrame(const std::string& technique, ParticleLighting lighting) {
  static const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings = settingsFor(technique, 128, 72);
  if (technique == "forward") settings = test::reference(settings);
  settings.particles = "smoke";
  settings.particleCount = 1024;
  settings.particleLighting = lighting;
  return renderParticles(scene, settings, kSmokeSteps);
}

class SmokeMatchesForward : public ::testing::TestWithParam<ParticleLighting> {};

// The light lists (lll) and the light grids (tiled, clustered: smoke in front of the opaque
// surfaces walks their front slice) light the smoke as every light does.
TEST_P(SmokeMatchesForward, InLllTiledAndClustered) {
  const ParticleFrame forward = smokeFrame("forward", GetParam());
  EXPECT_GT(forward.counters.dispatch.w, 600u);  // 1024 / 6 spawns a second for 5 s, less the dead
  for (const char* technique : {"lll", "tiled", "clustered"}) {
    const ParticleFrame frame = smokeFrame(technique, GetParam());
    test::expectWithinBound(frame.image.ldr, forward.image.ldr, test::kSmokeBound,
                            fmt::format("{} smoke {}-lit", technique, GetParam()));
  }
  // The smoke is really in the picture: forward without it differs.
  RenderSettings clear = settingsFor("forward", 128, 72);
  const test::Rendered noSmoke = test::render(loadScene(SceneRequest{"atrium", 0, 1}), clear);
  EXPECT_LT(test::psnr(noSmoke.ldr, forward.image.ldr), 30.0);
}

INSTANTIATE_TEST_SUITE_P(Lightings, SmokeMatchesForward,
                         ::testing::Values(ParticleLighting::Pixel, ParticleLighting::Vertex),
                         [](const auto& info) { return std::string(nameOf(info.param)); });

double totalLuminance(const HdrImage& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    sum += 0.2126 * image.rgba[i] + 0.7152 * image.rgba[i + 1] + 0.0722 * image.rgba[i + 2];
  return sum;
}

TEST(SmokeInOtherTechniques, DeferredAndPrepassLightItForwardDeferredUnlitLeavesItDark) {
  const ParticleFrame forward = smokeFrame("forward", ParticleLighting::Pixel);
  const ParticleFrame deferred = smokeFrame("deferred", ParticleLighting::Pixel);
  const ParticleFrame prepass = smokeFrame("prepass", ParticleLighting::Pixel);
  test::expectWithinBound(deferred.image.ldr, forward.image.ldr, test::kSmokeBound,
                          "deferred smoke pixel-lit");
  test::expectWithinBound(prepass.image.ldr, forward.image.ldr, test::kPrepassBound,
                          "prepass smoke pixel-lit");
  static const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings = settingsFor("deferred", 128, 72);
  settings.particles = "smoke";
  settings.particleCount = 1024;
  settings.deferredTranslucent = TranslucentLighting::Unlit;
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
  // The light behind the wall changes no pixel in front of it, on the glass or anywhere else (up to
  // rounding: on a GPU the lights of a list are summed in the order atomics made it).
  test::expectWithinBound(both.ldr, front.ldr, test::ImageBound{55.0, 1, 1.0, 1},
                          "glass, light behind the wall");
  const glm::vec3 glassBoth = meanColor(both.hdr, 76, 41, 8);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(glassBoth[c], glassLit[c], 1e-3f * glassLit[c]);
  // And lll gives forward's image.
  const test::Rendered reference = test::render(glassScene(true, true), test::reference(settings));
  test::expectWithinBound(both.ldr, reference.ldr, test::kSameImage, "lll glass");
}

}  // namespace
}  // namespace lll

namespace lll {
namespace {

using namespace test;

// A grey wall at z = 0, a 2 m pane of glass (coverage 0.4) at z = 1 when `pane`, seen from z = 5;
// no light near the middle, where the puff glows by itself.
Scene paneScene(bool pane) {
  Scene scene = glassScene(false, false);
  if (!pane) scene.instances.pop_back();  // glassScene adds the pane last
  return scene;
}

// A glowing puff between the wall and the pane (z = 0.5) is drawn before the glass, so the pane
// covers it as it covers the wall: through glass of coverage a, the difference the puff makes is
// (1 - a) times the difference it makes with no pane (radiance, so exact up to fp16 rounding). Drawn
// after the glass, as before, it showed over the pane at nearly full strength (0.99 of it here).
TEST(GlassAndParticles, AParticleBehindAPaneIsSeenThroughIt) {
  json preset = stillPreset();
  preset["count"] = 1;
  preset["emitter"] = {{"shape", "point"}, {"radius", 0}, {"offset", {0, 0, 0}}};
  preset["size"] = {0.4};
  preset["opacity"] = {0.8};
  preset["emission"] = {3.0};
  preset["softness"] = 0.01;
  const std::string presetPath = writePreset(preset, "behind-pane");
  struct Case {
    const char* technique;
    ParticleRender render;
  };
  for (const Case c : {Case{"forward", ParticleRender::Raster}, Case{"forward", ParticleRender::Compute},
                       Case{"lll", ParticleRender::Compute}}) {
    SCOPED_TRACE(fmt::format("{} {}", c.technique, c.render));
    RenderSettings settings = settingsFor(c.technique, 160, 90);
    const Rendered withoutPuff[2] = {render(paneScene(false), settings), render(paneScene(true), settings)};
    settings.particles = presetPath;
    settings.particleRender = c.render;
    settings.particleEmitter = "0,0,0.5";
    const ParticleFrame withPuff[2] = {renderParticles(paneScene(false), settings, 2),
                                       renderParticles(paneScene(true), settings, 2)};
    ASSERT_EQ(withPuff[1].counters.dispatch.w, 1u);
    const glm::vec3 open =
        meanColor(withPuff[0].image.hdr, 78, 43, 4) - meanColor(withoutPuff[0].hdr, 78, 43, 4);
    const glm::vec3 throughGlass =
        meanColor(withPuff[1].image.hdr, 78, 43, 4) - meanColor(withoutPuff[1].hdr, 78, 43, 4);
    ASSERT_GT(open.g, 0.5f) << "the puff does not show";
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(throughGlass[i] / open[i], 0.6f, 0.02f) << "channel " << i;
    // Beside the pane (x = 1.3 m) there is neither puff nor glass: no change at all.
    const glm::vec3 beside =
        meanColor(withPuff[1].image.hdr, 125, 43, 4) - meanColor(withoutPuff[1].hdr, 125, 43, 4);
    EXPECT_LT(glm::length(beside), 1e-3f);
  }
}

// A cloud of puffs through the pane, on both sides of it, at half resolution: the composite blends
// the layer in front of the pane and the one behind it; with four workgroups a tile each layer is
// four groups' blends, which particles-merge combines into group 0's before either resolve reads it.
// The image must be the one group's (a merge that dropped the groups of either layer loses the
// puffs of the slabs behind the first).
TEST(GlassAndParticles, GroupsMergedOnBothSidesOfThePane) {
  json preset = stillPreset();
  preset["count"] = 16384;          // four slabs
  preset["lifetime"] = {1.0, 1.0};  // all of them alive after a second
  preset["emitter"] = {{"shape", "sphere"}, {"radius", 0.9}, {"offset", {0, 0, 0}}};
  preset["size"] = {0.1};
  preset["opacity"] = {0.25};
  preset["emission"] = {1.5};
  RenderSettings settings = settingsFor("lll", 160, 90);
  settings.particles = writePreset(preset, "through-pane");
  settings.particleEmitter = "0,0,1";  // the sphere about the pane
  settings.particleRender = ParticleRender::Compute;
  settings.particleResolution = ParticleResolution::Half;
  settings.particleTileGroups = 4;
  const ParticleFrame many = renderParticles(paneScene(true), settings, 50);
  settings.particleTileGroups = 1;
  const ParticleFrame one = renderParticles(paneScene(true), settings, 50);
  const Rendered none = render(paneScene(true), settingsFor("lll", 160, 90));
  uint32_t inFront = 0, behind = 0;
  for (const gpu::Particle& p : many.particles) {
    if (!alive(p)) continue;
    (p.positionAge.z > 1.0f ? inFront : behind) += 1;
  }
  EXPECT_GT(inFront, 4000u);
  EXPECT_GT(behind, 4000u);
  EXPECT_EQ(stat(many.image, "particle_tile_groups"), 4.0);
  EXPECT_EQ(stat(one.image, "particle_tile_groups"), 1.0);
  // The puffs show: the middle is brighter than without them.
  const glm::vec3 glow = meanColor(many.image.hdr, 80, 45, 6) - meanColor(none.hdr, 80, 45, 6);
  EXPECT_GT(glow.g, 0.2f);
  expectWithinBound(many.image.ldr, one.image.ldr, kSmokeBound,
                    "four groups a tile against one, about a pane");
}

}  // namespace
}  // namespace lll
