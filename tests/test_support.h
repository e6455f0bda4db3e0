#pragma once
// Shared by the GPU tests: one Vulkan context per test binary on the device `auto` picks
// (lavapipe in CI), validation on when LLL_TEST_VALIDATION is set (ctest sets it), and helpers to
// render a scene and compare images.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "gpu/context.h"
#include "render/renderer.h"

namespace lll::test {

inline Context& gpuContext() {
  static std::unique_ptr<Context> context = [] {
    ContextOptions options;
    options.validation = std::getenv("LLL_TEST_VALIDATION") != nullptr;
    options.quiet = true;
    return std::make_unique<Context>(options);
  }();
  return *context;
}

struct Rendered {
  HdrImage hdr;
  LdrImage ldr;
  FrameResult frame;
  std::vector<std::pair<std::string, double>> stats;
};

// Renders one frame and fails the current test on any new validation message.
inline Rendered render(const Scene& scene, const RenderSettings& settings) {
  Context& context = gpuContext();
  const size_t before = context.validationMessages().size();
  Renderer renderer(context, scene, settings);
  Rendered out;
  out.frame = renderer.renderFrame(true);
  out.hdr = renderer.hdrImage();
  out.ldr = renderer.ldrImage();
  out.stats = renderer.technique().stats();
  const auto messages = context.validationMessages();
  for (size_t i = before; i < messages.size(); ++i) ADD_FAILURE() << messages[i];
  return out;
}

// A technique statistic of a rendered frame (Technique::stats); a missing one fails the test.
inline double stat(const Rendered& rendered, const std::string& name) {
  for (const auto& [key, value] : rendered.stats)
    if (key == name) return value;
  ADD_FAILURE() << "no stat " << name;
  return -1.0;
}

// Peak signal-to-noise ratio of two 8-bit images over RGB, in dB (infinity when identical).
inline double psnr(const LdrImage& a, const LdrImage& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < a.rgba.size() && i < b.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const double d = double(a.rgba[i]) - double(b.rgba[i]);
    sum += d * d;
    ++count;
  }
  const double mse = sum / double(std::max<size_t>(count, 1));
  return mse == 0.0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / mse);
}

}  // namespace lll::test
