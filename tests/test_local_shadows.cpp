// The local lights' shadows (shadows/local_shadows.h): which lights cast (importance on screen,
// stable from frame to frame), their views, the options, and in images every technique against
// forward with the same shadows. The exact edges are tested in test_analytic.cpp (a spot and a point
// light over an occluder, every shading path).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "camera_uniforms.h"
#include "core/errors.h"
#include "particle_test_support.h"
#include "render/settings.h"
#include "scene/lights.h"
#include "shadows/local_shadows.h"
#include "shadows/shadow_casters.h"
#include "test_support.h"

namespace lll {
namespace {

using test::cameraAt;

Light spot(glm::vec3 position, float intensity, float range = 5.0f) {
  Light light;
  light.type = LightType::Spot;
  light.position = position;
  light.direction = {0.0f, -1.0f, 0.0f};
  light.intensity = intensity;
  light.range = range;
  light.innerConeAngle = 0.4f;
  light.outerConeAngle = 0.6f;
  return light;
}

// The camera at the origin looking down -z.
const gpu::FrameUniforms kFrame = cameraAt({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f});

TEST(LocalShadowImportance, FollowsScreenCoverageAndIntensity) {
  const float ahead = shadowImportance(spot({0, 0, -20}, 10.0f), kFrame);
  EXPECT_GT(ahead, 0.0f);
  EXPECT_FLOAT_EQ(shadowImportance(spot({0, 0, -20}, 20.0f), kFrame), 2.0f * ahead) << "twice as bright";
  EXPECT_LT(shadowImportance(spot({0, 0, -40}, 10.0f), kFrame), 0.3f * ahead) << "twice as far: a quarter";
  EXPECT_EQ(shadowImportance(spot({0, 0, 20}, 10.0f), kFrame), 0.0f) << "behind the camera";
  EXPECT_EQ(shadowImportance(spot({40, 0, -10}, 10.0f), kFrame), 0.0f) << "beside the frustum";
  EXPECT_GT(shadowImportance(spot({6, 0, -5}, 10.0f), kFrame), 0.0f) << "outside, but reaching into it";
  EXPECT_FLOAT_EQ(shadowImportance(spot({0, 0, -2}, 10.0f), kFrame), 10.0f) << "the camera inside its reach";
  Light box = makeBoxLight({0, 0, -5}, {1, 0, 0}, {0, 1, 0}, glm::vec3(1.0f), glm::vec3(1.0f), 10.0f);
  EXPECT_EQ(shadowImportance(box, kFrame), 0.0f) << "box lights cast no shadow";
  EXPECT_EQ(shadowImportance(spot({0, 0, -20}, 10.0f, 1e30f), kFrame), 0.0f) << "no finite view";
}

// A light record starts with no shadow views (spotParams.w 0): only the frames' choices give it some,
// so a light that does not cast reads no other light's shadow.
TEST(LocalShadowViews, LightRecordsStartWithNone) {
  Light point = spot({0, 0, 0}, 10.0f);
  point.type = LightType::Point;
  EXPECT_EQ(toGpuLight(spot({0, 0, 0}, 10.0f)).spotParams.w, 0.0f);
  EXPECT_EQ(toGpuLight(point).spotParams.w, 0.0f);
}

TEST(LocalShadowSelection, TheMostImportantAndStable) {
  std::vector<Light> lights;
  for (int i = 0; i < 10; ++i) lights.push_back(spot({0.0f, 0.0f, -20.0f}, 10.0f + float(i)));
  lights.push_back(spot({0.0f, 0.0f, 30.0f}, 1000.0f));  // behind the camera: never
  std::vector<uint32_t> chosen = selectShadowLights(lights, kFrame, 3, {});
  EXPECT_EQ(chosen, (std::vector<uint32_t>{9, 8, 7}));
  // Last frame's lights (intensities 19, 18, 17) keep casting against newcomers up to kKeepShadow
  // times more important, and no further.
  lights[0].intensity = 25.0f;
  chosen = selectShadowLights(lights, kFrame, 3, std::vector<uint32_t>{9, 8, 7});
  std::sort(chosen.begin(), chosen.end());
  EXPECT_EQ(chosen, (std::vector<uint32_t>{7, 8, 9})) << "25 does not beat 17 x 1.5";
  lights[0].intensity = 26.0f;
  chosen = selectShadowLights(lights, kFrame, 3, std::vector<uint32_t>{9, 8, 7});
  std::sort(chosen.begin(), chosen.end());
  EXPECT_EQ(chosen, (std::vector<uint32_t>{0, 8, 9})) << "26 beats 17 x 1.5";
  EXPECT_TRUE(selectShadowLights(lights, kFrame, 0, {}).empty());
  EXPECT_EQ(selectShadowLights(lights, kFrame, 100, {}).size(), 10u)
      << "only lights with something on screen";
}

// A spot's view covers its cone; a point light's six faces cover every direction, each point in the
// face its major axis names (the lookup's choice, common/local_shadow.glsl), inside the margin.
TEST(LocalShadowViews, CoverTheLightsReach) {
  Light s = spot({1.0f, 2.0f, 3.0f}, 10.0f, 8.0f);
  s.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  const std::vector<LightView> spotViews = shadowViews(s, 256);
  ASSERT_EQ(spotViews.size(), 1u);
  Light point = s;
  point.type = LightType::Point;
  const std::vector<LightView> cube = shadowViews(point, 256);
  ASSERT_EQ(cube.size(), 6u);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  for (int i = 0; i < 2000; ++i) {
    glm::vec3 d(unit(random), unit(random), unit(random));
    if (glm::length(d) < 0.1f || glm::length(d) > 1.0f) continue;
    const glm::vec3 p = s.position + d * 7.0f;
    const glm::vec3 a = glm::abs(d);
    const int face = a.x >= a.y && a.x >= a.z ? (d.x > 0 ? 0 : 1)
                     : a.y >= a.z             ? (d.y > 0 ? 2 : 3)
                                              : (d.z > 0 ? 4 : 5);
    const glm::vec4 clip = cube[face].viewProj * glm::vec4(p, 1.0f);
    ASSERT_GT(clip.w, 0.0f);
    EXPECT_LE(std::abs(clip.x / clip.w), 1.0f - 1e-3f);
    EXPECT_LE(std::abs(clip.y / clip.w), 1.0f - 1e-3f);
    EXPECT_GT(clip.z / clip.w, 0.0f);
    EXPECT_LT(clip.z / clip.w, 1.0f);
    const glm::vec4 sc = spotViews[0].viewProj * glm::vec4(p, 1.0f);
    if (glm::dot(glm::normalize(d), s.direction) > std::cos(s.outerConeAngle)) {
      EXPECT_LE(std::abs(sc.x / sc.w), 1.0f);
      EXPECT_LE(std::abs(sc.y / sc.w), 1.0f);
    }
  }
  // A caster box beside the spot's cone is not drawn into it; one under it is.
  Bounds under, beside;
  under.expand(s.position + s.direction * 4.0f - glm::vec3(0.2f));
  under.expand(s.position + s.direction * 4.0f + glm::vec3(0.2f));
  beside.expand(s.position + glm::vec3(6.0f, 0.0f, 0.0f));
  beside.expand(s.position + glm::vec3(6.5f, 0.5f, 0.5f));
  EXPECT_TRUE(boxMayOverlapView(spotViews[0].viewProj, under));
  EXPECT_FALSE(boxMayOverlapView(spotViews[0].viewProj, beside));
}

TEST(LocalShadowOptions, RefusesValuesOutOfRange) {
  RenderSettings s;
  s.shadows = ShadowMode::All;
  EXPECT_EQ(localShadowOptions(s).lights, s.shadowLights);
  s.shadows = ShadowMode::Sun;
  EXPECT_EQ(localShadowOptions(s).lights, 0u) << "only --shadows all shadows local lights";
  s.shadowLights = 5000;
  EXPECT_THROW(localShadowOptions(s), InputError);
  s.shadowLights = 16;
  s.shadowLightResolution = 8;
  EXPECT_THROW(localShadowOptions(s), InputError);
}

// The atrium's own lights (points, and six spots) with the 16 most important casting: every
// technique, with its glass, shadows them as forward does on the same surfaces (the pre-pass within
// its own bound), and the shadows are in the picture.
TEST(LocalShadows, MatchForwardInEveryTechnique) {
  const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.shadows = ShadowMode::All;
  settings.shadowLights = 16;
  const test::Rendered onGbuffer = test::render(scene, test::reference(settings));
  EXPECT_EQ(test::stat(onGbuffer, "light-shadows"), 16.0);
  RenderSettings visibility = test::reference(settings);
  visibility.surfaces = SurfaceSource::Visibility;
  const test::Rendered onVisibility = test::render(scene, visibility);
  RenderSettings unshadowed = test::reference(settings);
  unshadowed.shadows = ShadowMode::Sun;
  EXPECT_LT(test::psnr(test::render(scene, unshadowed).ldr, onGbuffer.ldr), 40.0) << "no shadow in view";
  for (const char* technique : {"lll", "tiled", "clustered", "deferred", "prepass"}) {
    settings.technique = technique;
    const bool ownGbuffer = settings.technique == "prepass";
    const test::ImageBound bound = ownGbuffer ? test::kPrepassBound : test::kSameImage;
    test::expectWithinBound(test::render(scene, settings).ldr, ownGbuffer ? onGbuffer.ldr : onVisibility.ldr,
                            bound, std::string("light-shadowed atrium ") + technique);
  }
}

// Smoke scatters the shadowed lights as forward does (particles/scattering.glsl: the shadow at the
// particle), per pixel and once per particle.
TEST(LocalShadows, ShadowTheSmokeAsForwardDoes) {
  RenderSettings settings;
  settings.shadows = ShadowMode::All;
  settings.shadowLights = 16;
  test::expectSmokeLitAsForward(loadScene(SceneRequest{"atrium", 0, 1}), settings, "light-shadowed smoke");
}

// The casters drawn by the compute rasterizer (shadows/shadow_raster.h) give the hardware pass's
// shadows, cube faces and cones alike (small views: lavapipe's storage buffers hold the keys). At
// 100 texels the cells' corners are off the resolve's 8-texel tiles and 32-texel bins.
TEST(LocalShadows, ComputeRasterizedShadowsMatchTheHardwares) {
  const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  for (const uint32_t texels : {128u, 100u}) {
    RenderSettings settings;
    settings.width = 160;
    settings.height = 90;
    settings.technique = "lll";
    settings.shadows = ShadowMode::All;
    settings.shadowLights = 16;
    settings.shadowLightResolution = texels;
    settings.shadowRaster = RasterChoice::Hardware;
    const test::Rendered hardware = test::render(scene, settings);
    settings.shadowRaster = RasterChoice::Compute;
    const test::Rendered compute = test::render(scene, settings);
    EXPECT_EQ(test::stat(compute, "light-shadow-compute-raster"), 1.0);
    test::expectWithinBound(compute.ldr, hardware.ldr, test::kSameImage,
                            fmt::format("light shadows drawn in compute, {}-texel views", texels));
  }
}

// 300 spot lights, 64 of them a hundred times brighter and close to where the camera looks: with
// K = 64 exactly those 64 cast.
TEST(LocalShadows, ThreeHundredSpotsShadowTheRight64) {
  Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  const Camera& camera = scene.cameras[0];
  const Bounds bounds = scene.worldBounds();
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  scene.lights.clear();
  std::vector<uint32_t> bright;
  for (uint32_t i = 0; i < 300; ++i) {
    const bool isBright = i % 4 == 1 && bright.size() < 64;
    glm::vec3 p =
        bounds.min + (bounds.max - bounds.min) * glm::vec3(unit(random), unit(random), unit(random));
    if (isBright)
      p = camera.target + glm::vec3(unit(random) - 0.5f, unit(random), unit(random) - 0.5f) * 4.0f;
    if (isBright) bright.push_back(i);
    scene.lights.push_back(spot(p, isBright ? 100.0f : 1.0f));
  }
  ASSERT_EQ(bright.size(), 64u);
  RenderSettings settings;
  settings.width = 96;
  settings.height = 54;
  settings.technique = "lll";
  settings.shadows = ShadowMode::All;
  settings.shadowLights = 64;
  Context& context = test::gpuContext();
  const size_t before = context.validationMessages().size();
  Renderer renderer(context, scene, settings);
  renderer.renderFrame(true);
  std::vector<uint32_t> shadowed = renderer.lightShadows().shadowed();
  std::sort(shadowed.begin(), shadowed.end());
  EXPECT_EQ(shadowed, bright);
  // A second frame from the same camera keeps every light in its cell.
  renderer.renderFrame(true);
  std::vector<uint32_t> again = renderer.lightShadows().shadowed();
  std::sort(again.begin(), again.end());
  EXPECT_EQ(again, bright);
  test::expectNoValidationMessagesSince(before);
}

TEST(LocalShadows, AnAtlasTooLargeForTheDeviceIsRefused) {
  const Scene scene = loadScene(SceneRequest{"atrium", 0, 1});
  RenderSettings settings;
  settings.width = 64;
  settings.height = 36;
  settings.shadows = ShadowMode::All;
  settings.shadowLights = 1024;
  settings.shadowLightResolution = 4096;
  const std::string message = test::refusalOf(scene, settings);  // a 40 GiB atlas
  EXPECT_NE(message.find("--shadow-lights 1024"), std::string::npos) << message;
  EXPECT_NE(message.find("at most"), std::string::npos) << message;
}

}  // namespace
}  // namespace lll
