#pragma once
// Shared by the GPU tests: one Vulkan context per test binary on the device LLL_TEST_DEVICE names
// (auto | gpu | cpu | INDEX as `--device`; default cpu, lavapipe, so CI and a GPU machine run the
// same thing unless asked), validation on when LLL_TEST_VALIDATION is set (ctest sets it; it
// includes synchronization validation, and GPU-assisted validation with LLL_TEST_GPU_ASSISTED),
// and helpers to render a scene and compare images (image_bound.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <ostream>
#include <string>

#include "core/errors.h"
#include "gpu/context.h"
#include "image_bound.h"
#include "renderer/renderer.h"
#include "scene/builtin_scenes.h"
#include "scene/scene_source.h"

namespace lll {

// An option's name in a test's failure message (EXPECT_... << LllFill::Ray) and a parameter's name.
template <NamedEnum E>
std::ostream& operator<<(std::ostream& out, E value) {
  return out << nameOf(value);
}

}  // namespace lll

namespace lll::test {

inline constexpr float kPi = 3.14159265358979f;

inline Context& gpuContext() {
  static std::unique_ptr<Context> context = [] {
    ContextOptions options;
    const char* device = std::getenv("LLL_TEST_DEVICE");
    options.device = device != nullptr && *device ? device : "cpu";
    options.validation = std::getenv("LLL_TEST_VALIDATION") != nullptr;
    options.gpuAssisted = options.validation && std::getenv("LLL_TEST_GPU_ASSISTED") != nullptr;
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

// Fails the current test on each validation message of gpuContext() after the first `before`.
inline void expectNoValidationMessagesSince(size_t before) {
  const auto messages = gpuContext().validationMessages();
  for (size_t i = before; i < messages.size(); ++i) ADD_FAILURE() << messages[i];
}

// Renders one frame with `renderer` (made on gpuContext()) and fails the current test on any new
// validation message.
inline Rendered render(Renderer& renderer) {
  const size_t before = gpuContext().validationMessages().size();
  Rendered out;
  out.frame = renderer.renderFrame(true);
  out.hdr = renderer.hdrImage();
  out.ldr = renderer.ldrImage();
  out.stats = renderer.stats();
  expectNoValidationMessagesSince(before);
  return out;
}

// Renders one frame of a new Renderer, as render(Renderer&); its creation is checked too.
inline Rendered render(const Scene& scene, const RenderSettings& settings) {
  const size_t before = gpuContext().validationMessages().size();
  Renderer renderer(gpuContext(), scene, settings);
  expectNoValidationMessagesSince(before);
  return render(renderer);
}

// The message of the InputError a Renderer of `scene` with `settings` refuses them with; a test
// failure (and an empty message) where it accepts them.
inline std::string refusalOf(const Scene& scene, const RenderSettings& settings) {
  try {
    Renderer renderer(gpuContext(), scene, settings);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the renderer accepted what it should refuse";
  return {};
}

// The brute-force reference every technique is compared with: forward shading on the geometry
// (the depth prepass, then every light per fragment), independent of the visibility buffer's
// surface rebuild that the techniques use by default. Its glass is the caller's (compute by
// default: depth order; test_glass.cpp checks it against the geometry pass's).
inline RenderSettings reference(RenderSettings settings) {
  settings.technique = "forward";
  settings.surfaces = SurfaceSource::Gbuffer;
  return settings;
}

// A scene the image tests render: a built-in scene, or the glTF of an asset folder under
// LLL_ASSETS_DIR, with `lights` random lights (seed 3) added.
struct SceneWithLights {
  std::string scene;
  uint32_t lights;
};

inline Scene loadSceneWithLights(const SceneWithLights& c) {
  const bool builtin = makeBuiltinScene(c.scene).has_value();
  const std::string path =
      builtin ? c.scene : std::string(LLL_ASSETS_DIR) + "/" + c.scene + "/" + c.scene + ".gltf";
  return loadScene(SceneRequest{path, c.lights, 3});
}

// A technique statistic of a rendered frame (Technique::stats); a missing one fails the test.
inline double stat(const Rendered& rendered, const std::string& name) {
  for (const auto& [key, value] : rendered.stats)
    if (key == name) return value;
  ADD_FAILURE() << "no stat " << name;
  return -1.0;
}

}  // namespace lll::test
