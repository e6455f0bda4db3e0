// The sun (directional lights: KHR_lights_punctual "directional" or --sun): it reaches every pixel
// through the frame's uniforms, never a light list, so every technique must light surfaces, glass
// and smoke with it exactly as forward does. (The analytic plane is in test_analytic.cpp; the
// glTF light in test_gltf_loader.cpp; its photons in test_gi.cpp.)
#include <gtest/gtest.h>

#include "core/errors.h"
#include "particle_test_support.h"
#include "test_support.h"

namespace lll {
namespace {

// Low in the sky over the courtyard's long axis, warm.
const char* const kSun = "0.4,0.6,0.25,2,1,0.9,0.75";

Scene sunlitAtrium() {
  SceneRequest request{"atrium", 0, 1};
  request.suns = {kSun};
  return loadScene(request);
}

TEST(Sun, EveryTechniqueMatchesForward) {
  const Scene scene = sunlitAtrium();
  ASSERT_EQ(scene.directionalLights.size(), 1u);
  RenderSettings settings;
  settings.width = 128;
  settings.height = 72;
  const test::Rendered reference = test::render(scene, test::reference(settings));
  // The sun is in the picture: without it the courtyard differs.
  const test::Rendered sunless =
      test::render(loadScene(SceneRequest{"atrium", 0, 1}), test::reference(settings));
  EXPECT_LT(test::psnr(sunless.ldr, reference.ldr), 30.0);
  for (const char* technique : {"forward", "lll", "tiled", "clustered", "deferred", "prepass"}) {
    settings.technique = technique;
    const test::ImageBound bound = settings.technique == "prepass" ? test::kPrepassBound : test::kSameImage;
    test::expectWithinBound(test::render(scene, settings).ldr, reference.ldr, bound,
                            std::string("sunlit atrium ") + technique);
  }
}

// The courtyard under a sun strong enough to dominate it (20 lux against its 110 lamps).
Scene brightlySunlitAtrium() {
  SceneRequest request{"atrium", 0, 1};
  request.suns = {"0.4,0.6,0.25,20,1,0.9,0.75"};
  return loadScene(request);
}

// The sun's shadow (shadows/sun_shadows.h) with the sun strong enough to dominate the courtyard:
// every technique, with its glass, shadows it as forward does (the pre-pass through its 8-bit
// screen-space buffer, within its own bound), and the shadows are in the picture. Each is compared
// with forward on the same surfaces: on the H200 the visibility buffer's rebuilt surfaces and the
// raster G-buffer's differ slightly (at 20 lux, unshadowed, about 6 pixels of 160x90 beyond 2/255), and
// shadow lookups from their slightly different points add more where a PCF tap sits at an edge
// (15 pixels, up to 13/255); this test is about the techniques agreeing on one surface path.
TEST(Sun, ShadowsMatchForwardInEveryTechnique) {
  const Scene scene = brightlySunlitAtrium();
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  const test::Rendered onGbuffer = test::render(scene, test::reference(settings));
  RenderSettings visibility = test::reference(settings);
  visibility.surfaces = SurfaceSource::Visibility;
  const test::Rendered onVisibility = test::render(scene, visibility);
  RenderSettings unshadowed = test::reference(settings);
  unshadowed.shadows = ShadowMode::None;
  EXPECT_LT(test::psnr(test::render(scene, unshadowed).ldr, onGbuffer.ldr), 30.0) << "no shadow in view";
  for (const char* technique : {"lll", "tiled", "clustered", "deferred", "prepass"}) {
    settings.technique = technique;
    // The pre-pass shades its own raster buffers; deferred's G-buffer comes from the visibility buffer.
    const bool ownGbuffer = settings.technique == "prepass";
    const test::ImageBound bound = settings.technique == "prepass" ? test::kPrepassBound : test::kSameImage;
    test::expectWithinBound(test::render(scene, settings).ldr, ownGbuffer ? onGbuffer.ldr : onVisibility.ldr,
                            bound, std::string("sun-shadowed atrium ") + technique);
  }
  settings.technique = "lll";
  settings.surfaces = SurfaceSource::Gbuffer;
  test::expectWithinBound(test::render(scene, settings).ldr, onGbuffer.ldr, test::kSameImage,
                          "sun-shadowed atrium lll on the raster G-buffer");
}

// The casters drawn by the compute rasterizer (shadows/shadow_raster.h) give the hardware pass's
// shadow: both follow Vulkan's coverage rules, so only snapping ties may differ.
TEST(Sun, ComputeRasterizedShadowsMatchTheHardwares) {
  const Scene scene = brightlySunlitAtrium();
  RenderSettings settings;
  settings.width = 160;
  settings.height = 90;
  settings.technique = "lll";
  settings.shadowResolution = 512;
  settings.shadowRaster = RasterChoice::Hardware;
  const test::Rendered hardware = test::render(scene, settings);
  settings.shadowRaster = RasterChoice::Compute;
  test::expectWithinBound(test::render(scene, settings).ldr, hardware.ldr, test::kSameImage,
                          "sun shadow drawn in compute");
}

// Smoke scatters the sun as it scatters a point light (particles/scattering.glsl), per pixel and
// once per particle.
TEST(Sun, LightsTheSmokeAsForwardDoes) {
  test::expectSmokeLitAsForward(sunlitAtrium(), RenderSettings{}, "sunlit smoke");
}

// --sun is checked like every other option.
TEST(Sun, BadSunOptionsAreRefused) {
  for (const char* bad :
       {"0,0,0,1", "0,1,0", "0,1,0,-1", "0,1,0,1,2,0,0", "0,1,x,1", "0,1,0,inf", "0,1,0,1,1"}) {
    SceneRequest request{"plane", 0, 1};
    request.suns = {bad};
    try {
      loadScene(request);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  SceneRequest tooMany{"plane", 0, 1};
  tooMany.suns.assign(gpu::kMaxDirectionalLights + 1, "0,1,0,1");
  EXPECT_THROW(loadScene(tooMany), InputError);
}

}  // namespace
}  // namespace lll
