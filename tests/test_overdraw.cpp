// Light-volume overdraw of "deferred": the fragment count of its light pass (a pipeline statistics
// query) is what Infinity says deferred lighting costs. It must follow the lights' screen
// coverage: larger ranges, more fragments, never more than one per light per pixel. ("prepass"
// does not report it: devices may count its stencil-marking draws, which have no fragment shader.)
#include <gtest/gtest.h>

#include "core/errors.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

TEST(LightVolumeOverdraw, FollowsTheLightsRange) {
  if (!test::gpuContext().pipelineStatistics()) GTEST_FAIL() << "the test device lacks pipeline statistics";
  RenderSettings settings;
  settings.technique = "deferred";
  settings.width = 128;
  settings.height = 72;
  const double pixels = double(settings.width) * settings.height;
  double fragments[2] = {};
  for (int i = 0; i < 2; ++i) {
    SceneRequest request{"atrium", 128, 7};
    request.lightRangeScale = i == 0 ? 0.5f : 2.0f;
    const test::Rendered r = test::render(loadScene(request), settings);
    fragments[i] = test::stat(r, "light-volume-fragments");
    EXPECT_DOUBLE_EQ(test::stat(r, "light-volume-overdraw"), fragments[i] / pixels);
    // A convex volume covers a pixel at most once: one fragment per drawn light and pixel at most.
    EXPECT_GT(fragments[i], 0.0);
    EXPECT_LE(fragments[i], test::stat(r, "lights-drawn") * pixels);
  }
  // Four times the range: the 128 added lights cover far more of the screen (the atrium's own 110
  // lights keep their ranges, so less than the 16x of the areas).
  EXPECT_GT(fragments[1], 2.0 * fragments[0]);
}

TEST(LightRangeScale, RejectsAbsurdFactors) {
  for (const float scale : {0.0f, -1.0f, 100.0f}) {
    SceneRequest request{"atrium", 4, 1};
    request.lightRangeScale = scale;
    EXPECT_THROW(loadScene(request), InputError) << scale;
  }
}

}  // namespace
}  // namespace lll
