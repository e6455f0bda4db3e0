#pragma once
// `lll view`: the renderer in a window with live controls (Dear ImGui), a fly/orbit camera,
// per-pass GPU timings, a particle preset editor, screenshots and drag-and-drop of glTF files.
// Built on the library's public API (lll.h) only.
#include <cstdint>
#include <optional>
#include <string>

#include "lll.h"

namespace lll::view {

struct ViewJob {
  SceneRequest scene;
  RenderSettings settings;  // width and height: the window's first size
  ContextOptions device;
  uint32_t frames = 0;                    // --frames N: draw N frames, then exit; 0: until closed
  std::optional<std::string> screenshot;  // --screenshot: the last frame's image (.png or .exr)
  std::optional<std::string> script;      // --script: replayed input (view/input_script.h)
  float resolutionScale = 1.0f;           // render resolution / window resolution
};

// Returns the exit code: 0, or 1 when validation spoke under --validate. Throws InputError for
// bad input (exit 2), other exceptions for failures.
int runView(const ViewJob& job);

}  // namespace lll::view
