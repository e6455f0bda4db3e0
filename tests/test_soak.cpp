// Long runs must not grow (issue 16): lavapipe once compiled, and never freed, a shader variant on
// every bind of a shader whose branches depended on uniform-block values, about 1 MB a frame. Each
// technique renders smoke for LLL_SOAK_FRAMES frames (default 120) in this process, every frame
// simulated and drawn; the resident memory after them must stay within 8 MB of frame 10's.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

constexpr double kAllowedGrowthMiB = 8.0;
constexpr uint32_t kWarmupFrames = 10;

double residentMiB() {
  std::ifstream statm("/proc/self/statm");
  size_t pages = 0, resident = 0;
  statm >> pages >> resident;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

uint32_t soakFrames() {
  const char* frames = std::getenv("LLL_SOAK_FRAMES");
  return frames ? uint32_t(std::strtoul(frames, nullptr, 10)) : 120u;
}

struct SoakCase {
  const char* name;
  const char* technique;
  const char* lllFill;
  const char* lllShade;
  const char* particleLighting;
};

class Soak : public ::testing::TestWithParam<SoakCase> {};

TEST_P(Soak, MemoryStaysFlatOverFrames) {
  const SoakCase& c = GetParam();
  const Scene scene = loadScene({});
  RenderSettings settings;
  settings.width = 64;
  settings.height = 36;
  settings.technique = c.technique;
  settings.lllFill = c.lllFill;
  settings.lllShade = c.lllShade;
  settings.particles = "smoke";
  settings.particleCount = 1024;
  settings.particleLighting = c.particleLighting;
  Context& context = test::gpuContext();
  const size_t messagesBefore = context.validationMessages().size();
  Renderer renderer(context, scene, settings);
  const uint32_t frames = soakFrames();
  double atWarmup = 0.0, peak = 0.0;
  for (uint32_t i = 1; i <= frames; ++i) {
    renderer.renderFrame(i == frames);
    if (i == kWarmupFrames) atWarmup = residentMiB();
    if (i >= kWarmupFrames) peak = std::max(peak, residentMiB());
  }
  std::printf("soak %s: %u frames, resident %.1f MiB at frame %u, peak %.1f MiB after (+%.2f)\n", c.name,
              frames, atWarmup, kWarmupFrames, peak, peak - atWarmup);
  EXPECT_LE(peak - atWarmup, kAllowedGrowthMiB);
  EXPECT_EQ(context.validationMessages().size(), messagesBefore);
}

INSTANTIATE_TEST_SUITE_P(Techniques, Soak,
                         ::testing::Values(SoakCase{"forward", "forward", "compute", "compute", "pixel"},
                                           SoakCase{"lll", "lll", "compute", "compute", "pixel"},
                                           SoakCase{"lll_ray_fragment_vertexlit", "lll", "ray", "fragment",
                                                    "vertex"},
                                           SoakCase{"deferred", "deferred", "compute", "compute", "pixel"},
                                           SoakCase{"prepass", "prepass", "compute", "compute", "pixel"}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace lll
