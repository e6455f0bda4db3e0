// Every scene a user is likely to render first: the default atrium and the four shared glTF scenes
// (with 64 random lights, since they bring none) render under validation with no message, no NaN or
// infinity, and a picture that is not black.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

struct SceneCase {
  std::string name;
  std::string path;  // empty for a built-in scene
};

std::ostream& operator<<(std::ostream& os, const SceneCase& c) {
  return os << c.name;
}

class ScenesRender : public ::testing::TestWithParam<SceneCase> {};

TEST_P(ScenesRender, FiniteAndNotBlack) {
  const SceneCase& c = GetParam();
  SceneRequest request;
  request.scene = c.path.empty() ? c.name : c.path;
  request.extraLights = c.path.empty() ? 0 : 64;
  std::vector<std::string> warnings;
  const Scene scene = loadScene(request, &warnings);
  for (const std::string& w : warnings) ADD_FAILURE() << "loader warning: " << w;
  ASSERT_FALSE(scene.lights.empty());

  RenderSettings settings;
  settings.width = 96;
  settings.height = 54;
  settings.technique = "forward";
  const test::Rendered out = test::render(scene, settings);
  ASSERT_EQ(out.hdr.width, 96u);
  ASSERT_EQ(out.hdr.height, 54u);
  ASSERT_EQ(out.hdr.rgba.size(), size_t(96) * 54 * 4);

  const size_t pixels = size_t(out.hdr.width) * out.hdr.height;
  size_t nonFinite = 0;
  double luminanceSum = 0.0;
  for (size_t i = 0; i < pixels; ++i) {
    const float* p = &out.hdr.rgba[i * 4];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(p[3])) {
      ++nonFinite;
      continue;
    }
    luminanceSum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
  }
  EXPECT_EQ(nonFinite, 0u) << "pixels with NaN or infinity";
  const double meanLuminance = luminanceSum / double(pixels);
  // The dimmest scene, the cave (a small lit island in the dark), has a mean of about 0.002.
  EXPECT_GT(meanLuminance, 5e-4) << "the picture is (nearly) black";

  // Non-black in the displayed image: a channel above 2 of 255, so rounding noise does not count.
  size_t lit = 0;
  for (size_t i = 0; i < pixels; ++i) {
    const uint8_t* p = &out.ldr.rgba[i * 4];
    if (std::max({p[0], p[1], p[2]}) > 2) ++lit;
  }
  const double litFraction = double(lit) / double(pixels);
  EXPECT_GE(litFraction, 0.10) << "too few pixels above black";  // space, mostly sky, has about 15%
  std::cout << c.name << ": mean luminance " << meanLuminance << ", " << litFraction * 100.0
            << "% above black\n";
}

// No prefix: the tests are ScenesRender.FiniteAndNotBlack/<scene>.
INSTANTIATE_TEST_SUITE_P(, ScenesRender,
                         ::testing::Values(SceneCase{"atrium", ""},
                                           SceneCase{"camp", LLL_ASSETS_DIR "/camp/camp.gltf"},
                                           SceneCase{"cave", LLL_ASSETS_DIR "/cave/cave.gltf"},
                                           SceneCase{"garage", LLL_ASSETS_DIR "/garage/garage.gltf"},
                                           SceneCase{"space", LLL_ASSETS_DIR "/space/space.gltf"}),
                         [](const ::testing::TestParamInfo<SceneCase>& info) { return info.param.name; });

}  // namespace
}  // namespace lll
