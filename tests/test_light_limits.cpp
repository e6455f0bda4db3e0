// Light counts against the device: the light array is one storage buffer, so a device whose
// largest storage buffer (maxStorageBufferRange) holds fewer lights than the product's cap refuses
// the scene with a message naming the limit and the largest count that fits.
#include <gtest/gtest.h>

#include <string>

#include "core/errors.h"
#include "render/frame.h"
#include "renderer/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"
#include "shared/gpu_types.h"
#include "shared/limits.h"
#include "test_support.h"

namespace lll {
namespace {

uint64_t lightsThatFit(const Context& context) {
  return context.properties().limits.maxStorageBufferRange / sizeof(gpu::GpuLight);
}

TEST(LightLimits, StorageBufferCheckNamesTheLargestCountThatFits) {
  const Context& context = test::gpuContext();
  const uint64_t fit = lightsThatFit(context);
  EXPECT_NO_THROW(requireStorageBufferFits(context, fit, sizeof(gpu::GpuLight), "the light array"));
  try {
    requireStorageBufferFits(context, fit + 1, sizeof(gpu::GpuLight), "the light array");
    ADD_FAILURE() << "one light more than fits was accepted";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(std::to_string(fit + 1) + " lights"), std::string::npos) << message;
    EXPECT_NE(message.find("maxStorageBufferRange"), std::string::npos) << message;
    EXPECT_NE(message.find("at most " + std::to_string(fit) + " lights"), std::string::npos) << message;
  }
}

// End to end where the device is the limit (lavapipe: 2,097,152 lights); where the device holds
// more than the cap, the cap is what stops a scene (tests/test_cli.cpp checks that refusal).
TEST(LightLimits, ARendererRefusesMoreLightsThanTheDeviceHolds) {
  Context& context = test::gpuContext();
  const uint64_t fit = lightsThatFit(context);
  if (fit >= gpu::kMaxLights) {
    EXPECT_GE(uint64_t(context.properties().limits.maxStorageBufferRange),
              uint64_t(gpu::kMaxLights) * sizeof(gpu::GpuLight));
    return;
  }
  SceneRequest request{"plane", uint32_t(fit), 1};  // the plane's own light makes it one too many
  const Scene scene = loadScene(request);
  ASSERT_EQ(scene.lights.size(), fit + 1);
  RenderSettings settings;
  settings.width = 32;
  settings.height = 18;
  settings.technique = "lll";
  const std::string message = test::refusalOf(scene, settings);
  EXPECT_NE(message.find("at most " + std::to_string(fit) + " lights"), std::string::npos) << message;
}

}  // namespace
}  // namespace lll
