// The sun's cascades, fitted on the CPU (shadows/sun_shadows.h): each covers its slice of the view,
// their texels stay fixed on the world as the camera moves and turns (no shimmer), and the options
// are checked. The shadows in images are tested in test_analytic.cpp (an occluder over the plane,
// every shading path) and test_sun.cpp (every technique against forward).
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "camera_uniforms.h"
#include "core/errors.h"
#include "render/settings.h"
#include "shadows/sun_shadows.h"

namespace lll {
namespace {

using test::cameraAt;

Bounds sceneBox() {
  Bounds b;
  b.expand(glm::vec3(-20.0f, -1.0f, -10.0f));
  b.expand(glm::vec3(20.0f, 15.0f, 10.0f));
  return b;
}

const glm::vec3 kTowardSun = glm::normalize(glm::vec3(0.4f, 0.6f, 0.25f));

// Where world point `p` falls in cascade `c`, in texels.
glm::vec2 texelOf(const gpu::SunShadow& s, uint32_t c, glm::vec3 p) {
  const glm::vec4 clip = s.cascadeViewProj[c] * glm::vec4(p, 1.0f);
  return (glm::vec2(clip) * 0.5f + 0.5f) * s.atlas.y;
}

TEST(SunShadowCascades, EachCoversItsSliceOfTheView) {
  const SunShadowOptions options;
  const gpu::FrameUniforms frame = cameraAt({3.0f, 2.0f, 8.0f}, {-5.0f, 1.0f, -2.0f});
  const gpu::SunShadow s = fitSunCascades(frame, kTowardSun, sceneBox(), options);
  ASSERT_EQ(s.config.x, options.cascades);
  const glm::mat4 toWorld = glm::inverse(frame.view);
  float previous = frame.depthParams.x;
  for (uint32_t c = 0; c < s.config.x; ++c) {
    EXPECT_GT(s.splits[c], previous);
    for (float d : {previous, s.splits[c]})
      for (float sx : {-1.0f, 1.0f})
        for (float sy : {-1.0f, 1.0f}) {
          const glm::vec3 corner(
              toWorld * glm::vec4(sx * frame.depthParams.z * d, sy * frame.depthParams.w * d, -d, 1.0f));
          const glm::vec4 clip = s.cascadeViewProj[c] * glm::vec4(corner, 1.0f);
          EXPECT_LE(std::abs(clip.x), 1.0f + 1e-4f) << "cascade " << c << " depth " << d;
          EXPECT_LE(std::abs(clip.y), 1.0f + 1e-4f) << "cascade " << c << " depth " << d;
        }
    previous = s.splits[c];
  }
  EXPECT_FLOAT_EQ(s.splits[s.config.x - 1], frame.depthParams.y);
  // The depth range holds the whole scene, nearest the sun at 1 (reverse depth).
  const Bounds b = sceneBox();
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
    const float z = (s.cascadeViewProj[0] * glm::vec4(corner, 1.0f)).z;
    EXPECT_GT(z, 0.0f);
    EXPECT_LT(z, 1.0f);
  }
  const glm::vec3 centre = b.center();
  EXPECT_GT((s.cascadeViewProj[0] * glm::vec4(centre + kTowardSun, 1.0f)).z,
            (s.cascadeViewProj[0] * glm::vec4(centre, 1.0f)).z);
}

// Moving the camera by a fraction of a texel, or turning it, moves each cascade by whole texels
// only: a static point keeps its place within its texel, so its shadow does not crawl.
TEST(SunShadowCascades, TexelsStayPutAsTheCameraMovesAndTurns) {
  const SunShadowOptions options;
  const gpu::SunShadow a =
      fitSunCascades(cameraAt({3.0f, 2.0f, 8.0f}, {-5.0f, 1.0f, -2.0f}), kTowardSun, sceneBox(), options);
  const gpu::SunShadow b = fitSunCascades(cameraAt({3.013f, 2.007f, 7.991f}, {-6.0f, 3.0f, 1.0f}), kTowardSun,
                                          sceneBox(), options);
  const glm::vec3 points[] = {{0.0f, 0.0f, 0.0f}, {1.3f, 0.2f, -0.7f}, {-2.1f, 4.0f, 1.9f}};
  int moved = 0;
  for (uint32_t c = 0; c < a.config.x; ++c) {
    EXPECT_FLOAT_EQ(a.texelWorld[c], b.texelWorld[c]) << "the cascade's size follows the slice alone";
    for (const glm::vec3& p : points) {
      const glm::vec2 shift = texelOf(b, c, p) - texelOf(a, c, p);
      EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3f) << "cascade " << c;
      EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3f) << "cascade " << c;
      if (glm::length(shift) > 0.5f) ++moved;
    }
  }
  EXPECT_GT(moved, 0) << "the turn moved no cascade: the test checks nothing";
}

TEST(SunShadowCascades, TheBrightestSunCasts) {
  std::vector<DirectionalLight> suns(3);
  suns[0].illuminance = 2.0f;
  suns[1].illuminance = 5.0f;
  suns[1].color = glm::vec3(0.1f);  // 0.5 lux of colour
  suns[2].illuminance = 1.0f;
  EXPECT_EQ(shadowCastingSun(suns), 0);
  suns[2].illuminance = 3.0f;
  EXPECT_EQ(shadowCastingSun(suns), 2);
  EXPECT_EQ(shadowCastingSun({}), -1);
}

TEST(SunShadowCascades, BadOptionsAreRefusedByName) {
  const auto refused = [](const std::function<void(RenderSettings&)>& change, const std::string& option) {
    RenderSettings s;
    change(s);
    try {
      sunShadowOptions(s);
      ADD_FAILURE() << option << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
    }
  };
  refused([](RenderSettings& s) { s.cascades = 0; }, "--cascades");
  refused([](RenderSettings& s) { s.cascades = gpu::kMaxCascades + 1; }, "--cascades");
  refused([](RenderSettings& s) { s.shadowResolution = 8; }, "--shadow-resolution");
  refused([](RenderSettings& s) { s.shadowResolution = 100000; }, "--shadow-resolution");
  RenderSettings none;
  none.shadows = ShadowMode::None;
  EXPECT_EQ(sunShadowOptions(none).cascades, 0u);
}

}  // namespace
}  // namespace lll
