// Long runs must not grow (issue 16): lavapipe once compiled, and never freed, a shader variant on
// every bind of a shader whose branches depended on uniform-block values, about 1 MB a frame. Each
// technique renders smoke (from its steady state) for LLL_SOAK_FRAMES frames (default 120) in this
// process, every frame simulated and drawn; the heap in use over its last 20 frames must stay
// within 8 MB of that over the 20 frames that end halfway through the run.
//
// The heap is measured on a context of its own without the validation layers: the Debian layer
// (1.3.239) keeps about 25 KB of its own per submitted frame (seen: +9.8 MB over 400 frames with
// LLL_TEST_VALIDATION, +0.0 without, the same renderer), which is not ours to bound. Validation
// over a run is still checked: the first frames of every case render on the shared, validated
// context too.
#include <gtest/gtest.h>
#include <malloc.h>
#ifdef __SANITIZE_ADDRESS__
// From the AddressSanitizer runtime (sanitizer/allocator_interface.h, which GCC does not install).
extern "C" size_t __sanitizer_get_current_allocated_bytes();
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "particles/presets.h"
#include "scene/scene_source.h"
#include "test_support.h"

namespace lll {
namespace {

// Above lavapipe's one 9.95 MB rasterizer block, which may be taken once after the baseline window
// and kept to the end (prepass under ASan with ctest -j 2: +10.00 MiB, 2026-11-28). A leak still
// shows: the windows' least values lie 35 frames apart on the shortest run, so a third of a MB a
// frame is enough to fail.
constexpr double kAllowedGrowthMiB = 12.0;
constexpr uint32_t kWarmupFrames = 10;
constexpr uint32_t kWindow = 20;

// Heap in use: what a leak grows. The resident set is too noisy to bound at 8 MB here: lavapipe's
// rasterizer threads take and give back several MB from frame to frame (seen 138 -> 145 -> 138).
// Under AddressSanitizer malloc is its own, and so is the count.
double heapInUseMiB() {
#ifdef __SANITIZE_ADDRESS__
  const double bytes = double(__sanitizer_get_current_allocated_bytes());
#else
  const struct mallinfo2 info = mallinfo2();
  const double bytes = double(info.uordblks) + double(info.hblkhd);
#endif
  return bytes / (1024.0 * 1024.0);
}

uint32_t soakFrames() {
  const char* frames = std::getenv("LLL_SOAK_FRAMES");
  return frames ? uint32_t(std::strtoul(frames, nullptr, 10)) : 120u;
}

// The test device, without validation layers.
Context& unvalidatedContext() {
  static std::unique_ptr<Context> context = [] {
    ContextOptions options;
    const char* device = std::getenv("LLL_TEST_DEVICE");
    options.device = device != nullptr && *device ? device : "cpu";
    options.quiet = true;
    return std::make_unique<Context>(options);
  }();
  return *context;
}

struct SoakCase {
  const char* name;
  const char* technique;
  LllFill lllFill;
  LllShade lllShade;
  ParticleLighting particleLighting;
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
  {
    Context& validated = test::gpuContext();
    const size_t messagesBefore = validated.validationMessages().size();
    Renderer renderer(validated, scene, settings);
    renderer.advanceParticles(stepsToSteadyState(renderer.particles()->preset()));
    for (uint32_t i = 1; i <= kWarmupFrames; ++i) renderer.renderFrame(i == kWarmupFrames);
    EXPECT_EQ(validated.validationMessages().size(), messagesBefore);
  }
  Renderer renderer(unvalidatedContext(), scene, settings);
  // A growing plume needs more of the rasterizer's memory each frame, legitimately: start from
  // the steady state, where as many particles die as are born.
  renderer.advanceParticles(stepsToSteadyState(renderer.particles()->preset()));
  const uint32_t frames = std::max(soakFrames(), 70u);  // baseline and end windows 15 frames apart
  // The least over a window of frames: a frame that happens to hold a large temporary is not a
  // leak, and a leak raises the least too. Seen with lavapipe: a 9.95 MB block alive after some
  // frames and not others (prepass, 200 frames, sampled every 5: absent at 20-35, 45, 60, 110,
  // 175, 190), the rasterizer's binning memory freed by its thread after the fence signals; and
  // in the full suite the same block taken once, early, and kept to the end of the case (deferred:
  // absent once in frames 10-29, present at every frame after; released during the next case).
  // So the baseline is the window that ends halfway through the run, once such one-time
  // allocations are made: a leak grows between there and the end just the same (1 MB a frame:
  // 35 MB over the shortest run).
  const uint32_t baselineFirst = frames / 2 - kWindow;
  double atWarmup = INFINITY, atEnd = INFINITY, peak = 0.0;
  const char* traceEnv = std::getenv("LLL_SOAK_TRACE");  // print the heap every N frames
  const uint32_t trace = traceEnv ? uint32_t(std::strtoul(traceEnv, nullptr, 10)) : 0u;
  for (uint32_t i = 1; i <= frames; ++i) {
    renderer.renderFrame(i == frames);
    const double heap = heapInUseMiB();
    if (trace != 0 && i % trace == 0) std::printf("soak %s: frame %u heap %.2f MiB\n", c.name, i, heap);
    if (i > baselineFirst && i <= baselineFirst + kWindow) atWarmup = std::min(atWarmup, heap);
    if (i > frames - kWindow) atEnd = std::min(atEnd, heap);
    peak = std::max(peak, heap);
  }
  std::printf(
      "soak %s: %u frames, heap in use %.1f MiB from frame %u, %.1f MiB at the end (%+.2f), peak %.1f\n",
      c.name, frames, atWarmup, baselineFirst + 1, atEnd, atEnd - atWarmup, peak);
  EXPECT_LE(atEnd - atWarmup, kAllowedGrowthMiB);
}

INSTANTIATE_TEST_SUITE_P(
    Techniques, Soak,
    ::testing::Values(
        SoakCase{"forward", "forward", LllFill::Compute, LllShade::Compute, ParticleLighting::Pixel},
        SoakCase{"lll", "lll", LllFill::Compute, LllShade::Compute, ParticleLighting::Pixel},
        SoakCase{"lll_ray_fragment_vertexlit", "lll", LllFill::Ray, LllShade::Fragment,
                 ParticleLighting::Vertex},
        SoakCase{"deferred", "deferred", LllFill::Compute, LllShade::Compute, ParticleLighting::Pixel},
        SoakCase{"prepass", "prepass", LllFill::Compute, LllShade::Compute, ParticleLighting::Pixel}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace lll
