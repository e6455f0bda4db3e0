#pragma once
// lll view's application: the loop, the state it edits and what it applies between frames
// (viewer.cpp), and its Dear ImGui panels (viewer_panels.cpp). Private to src/view/.
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lll.h"
#include "view/input_script.h"
#include "view/view_camera.h"
#include "view/viewer.h"
#include "view/window.h"

namespace lll::view {

class Imgui;  // Dear ImGui's context and backends (viewer.cpp)

class Viewer {
 public:
  explicit Viewer(const ViewJob& job);
  ~Viewer();
  int run();

 private:
  void loadInitialScene();
  // A new renderer from settings_, and first a new scene from request_ when `reload`; on bad input
  // the message is shown and what was there stays. True when it was replaced.
  bool rebuild(bool reload);
  void applyPendingChanges();
  void applyScriptEvents();
  void applyScriptSet(const ScriptEvent& e);
  CameraInput gatherInput();
  void writeScreenshot(const std::string& path);
  void savePreset(const std::string& path);
  void loadPresetForEditing();
  void applyPresetEdit();
  void printCamera();
  // viewer_panels.cpp: the Dear ImGui windows.
  void drawUi();
  void drawControls();
  void drawTimings();
  void drawPresetEditor();

  ViewJob job_;
  SceneRequest request_;         // as edited
  SceneRequest appliedRequest_;  // as loaded
  RenderSettings settings_;      // as edited
  RenderSettings applied_;       // as the renderer was made
  float scale_ = 1.0f;
  bool animate_ = false;
  float time_ = 0.0f;

  // Destroyed bottom to top: the renderer and ImGui before the window, the window before the device.
  std::unique_ptr<Context> context_;
  std::unique_ptr<Window> window_;
  std::unique_ptr<Imgui> imgui_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<ViewCamera> camera_;

  std::vector<ScriptEvent> script_;
  size_t nextEvent_ = 0;
  CameraInput scriptInput_;  // keys held by the script; look and wheel for one frame
  std::vector<std::string> drops_;
  float wheel_ = 0.0f;
  glm::dvec2 cursor_{0.0};
  bool looking_ = false;

  uint32_t frame_ = 0;
  FrameResult lastFrame_;
  std::deque<float> history_;
  std::vector<std::pair<std::string, double>> stats_;
  std::string message_;  // the last error or note, shown in the controls
  std::string cameraText_;
  bool screenshotKey_ = false;
  uint32_t screenshots_ = 0;
  bool showUi_ = true;

  bool editorOpen_ = false;
  std::optional<ParticlePreset> edited_;
  std::string presetPath_ = "preset.json";
  std::string presetMessage_;
};

}  // namespace lll::view
