#include "view/viewer.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>

#include "view/input_script.h"
#include "view/view_camera.h"
#include "view/window.h"

namespace lll::view {

namespace {

constexpr size_t kHistoryFrames = 240;  // the rolling frame-time graph

void checkImguiResult(VkResult result) {
  if (result != VK_SUCCESS) throwVulkanError("Dear ImGui's Vulkan backend", __FILE__, __LINE__, result);
}

// Dear ImGui's context, GLFW input and Vulkan drawing, torn down before the window and device.
class Imgui {
 public:
  Imgui(Context& context, Window& window) : device_(context.device()) {
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 16;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device_, &poolInfo, nullptr, &pool_));
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window.handle(), true);  // chains the viewer's own callbacks
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context.instance();
    info.PhysicalDevice = context.physicalDevice();
    info.Device = device_;
    info.QueueFamily = context.queueFamily();
    info.Queue = context.queue();
    info.DescriptorPool = pool_;
    info.MinImageCount = 2;
    info.ImageCount = std::max(window.imageCount(), 2u);
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = checkImguiResult;
    ImGui_ImplVulkan_Init(&info, window.renderPass());
    context.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  }
  ~Imgui() {
    vkDeviceWaitIdle(device_);
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    vkDestroyDescriptorPool(device_, pool_, nullptr);
  }
  Imgui(const Imgui&) = delete;
  Imgui& operator=(const Imgui&) = delete;

 private:
  VkDevice device_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
};

float sceneDiagonal(const Scene& scene) {
  const Bounds b = scene.worldBounds();
  return b.valid() ? glm::length(b.extent()) : 10.0f;
}

std::string lowercaseExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// A combo box over string choices; true when the value changed.
bool choice(const char* label, std::string& value, const std::vector<std::string>& options) {
  bool changed = false;
  if (ImGui::BeginCombo(label, value.c_str())) {
    for (const std::string& option : options) {
      const bool selected = option == value;
      if (ImGui::Selectable(option.c_str(), selected) && !selected) {
        value = option;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

bool choice(const char* label, uint32_t& value, const std::vector<uint32_t>& options) {
  bool changed = false;
  if (ImGui::BeginCombo(label, std::to_string(value).c_str())) {
    for (uint32_t option : options) {
      const bool selected = option == value;
      if (ImGui::Selectable(std::to_string(option).c_str(), selected) && !selected) {
        value = option;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// A number field that applies on Enter or when left (editing a light count must not reload the
// scene at every keystroke).
bool committedUint(const char* label, uint32_t& value, uint32_t lo, uint32_t hi) {
  uint32_t edited = value;
  ImGui::InputScalar(label, ImGuiDataType_U32, &edited);
  if (ImGui::IsItemDeactivatedAfterEdit()) {
    value = std::clamp(edited, lo, hi);
    return true;
  }
  return false;
}

// Keys over a particle's life: one slider per key, + and - to add or drop the last.
template <typename T, typename Edit>
bool curve(const char* label, std::vector<T>& keys, Edit edit) {
  bool changed = false;
  ImGui::PushID(label);
  ImGui::TextUnformatted(label);
  for (size_t i = 0; i < keys.size(); ++i) {
    ImGui::PushID(int(i));
    edit(keys[i]);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
    ImGui::PopID();
  }
  if (keys.size() < 8 && ImGui::SmallButton("+")) {
    keys.push_back(keys.back());
    changed = true;
  }
  ImGui::SameLine();
  if (keys.size() > 1 && ImGui::SmallButton("-")) {
    keys.pop_back();
    changed = true;
  }
  ImGui::PopID();
  return changed;
}

class Viewer {
 public:
  explicit Viewer(const ViewJob& job);
  int run();

 private:
  void loadInitialScene();
  bool reloadScene();
  bool rebuildRenderer();
  void applyPendingChanges();
  void applyScriptEvents();
  void applyScriptSet(const ScriptEvent& e);
  CameraInput gatherInput();
  void writeScreenshot(const std::string& path);
  void savePreset(const std::string& path);
  void loadPresetForEditing();
  void applyPresetEdit();
  void printCamera();
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

Viewer::Viewer(const ViewJob& job) : job_(job), request_(job.scene), settings_(job.settings) {
  scale_ = job.resolutionScale;
  animate_ = job.settings.animateLights;
  time_ = job.scene.time;
  if (job.script) script_ = loadInputScript(*job.script);
  if (job.screenshot) {
    const std::string ext = lowercaseExtension(*job.screenshot);
    if (ext != ".png" && ext != ".exr")
      throw InputError(
          fmt::format("--screenshot {}: expected a name ending in .png or .exr", *job.screenshot));
    checkOutputPath("--screenshot", *job.screenshot);
  }
  findTechnique(settings_.technique);
  validateResolution(settings_.width, settings_.height);
}

void Viewer::loadInitialScene() {
  std::vector<std::string> warnings;
  scene_ = std::make_unique<Scene>(loadScene(request_, &warnings));
  for (const std::string& w : warnings) fmt::print(stderr, "lll: warning: {}\n", w);
  particleOptions(*scene_, settings_);  // a bad preset fails before the window opens
  appliedRequest_ = request_;
}

int Viewer::run() {
  loadInitialScene();
  initGlfw();
  ContextOptions device = job_.device;
  device.instanceExtensions = surfaceInstanceExtensions();
  device.swapchain = true;
  // The window first, then the device that presents to it; destroyed in the opposite order.
  context_ = std::make_unique<Context>(device);
  window_ = std::make_unique<Window>("lll view", settings_.width, settings_.height);
  window_->attach(*context_);
  GLFWwindow* w = window_->handle();
  glfwSetWindowUserPointer(w, this);
  // Installed before ImGui's, which chain to them.
  glfwSetScrollCallback(w, [](GLFWwindow* window, double, double dy) {
    static_cast<Viewer*>(glfwGetWindowUserPointer(window))->wheel_ += float(dy);
  });
  glfwSetDropCallback(w, [](GLFWwindow* window, int count, const char** paths) {
    auto* self = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
    for (int i = 0; i < count; ++i) self->drops_.push_back(paths[i]);
  });
  imgui_ = std::make_unique<Imgui>(*context_, *window_);

  renderer_ = std::make_unique<Renderer>(*context_, *scene_, settings_);
  applied_ = settings_;
  camera_ = std::make_unique<ViewCamera>(renderer_->camera(), sceneDiagonal(*scene_));
  const bool fixedSteps = job_.frames > 0 || job_.script;
  auto last = std::chrono::steady_clock::now();

  while (!window_->shouldClose()) {
    glfwPollEvents();
    uint32_t fbWidth = 0, fbHeight = 0;
    window_->framebufferSize(fbWidth, fbHeight);
    if (fbWidth == 0 || fbHeight == 0) {  // minimised: wait for the window to come back
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    applyScriptEvents();
    settings_.width = std::clamp(uint32_t(std::lround(fbWidth * scale_)), 1u, 8192u);
    settings_.height = std::clamp(uint32_t(std::lround(fbHeight * scale_)), 1u, 8192u);
    applyPendingChanges();

    const auto now = std::chrono::steady_clock::now();
    const float seconds = fixedSteps ? kAnimationFrameSeconds
                                     : std::min(std::chrono::duration<float>(now - last).count(), 0.1f);
    last = now;
    camera_->update(gatherInput(), seconds);
    renderer_->setCamera(camera_->camera());
    if (animate_ && frame_ > 0) {
      time_ = std::min(time_ + kAnimationFrameSeconds, kMaxAnimationSeconds);
      renderer_->moveLightsTo(*scene_, time_);
    }
    const bool lastFrame = job_.frames > 0 && frame_ + 1 >= job_.frames;
    const bool capture = (lastFrame && job_.screenshot) || screenshotKey_;
    try {
      lastFrame_ = renderer_->renderFrame(capture);
    } catch (const InputError& e) {  // a camera flown out of any sensible range
      message_ = e.what();
      camera_->reset(resolveCamera(*scene_, ""));
      continue;
    }
    if (lastFrame_.passes.size() > 0) {
      history_.push_back(float(lastFrame_.passes.back().ms));
      if (history_.size() > kHistoryFrames) history_.pop_front();
    }
    stats_ = renderer_->stats();
    if (capture && lastFrame && job_.screenshot) writeScreenshot(*job_.screenshot);
    if (screenshotKey_) {
      const std::string name = fmt::format("lll-view-{}", ++screenshots_);
      writeScreenshot(name + ".png");
      writeScreenshot(name + ".exr");
      message_ = fmt::format("wrote {}.png and {}.exr", name, name);
      screenshotKey_ = false;
    }

    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    if (showUi_) drawUi();
    ImGui::Render();
    window_->present(renderer_->displayImage(), renderer_->displayLayout(),
                     [](VkCommandBuffer cmd) { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); });
    ++frame_;
    if (lastFrame) break;
  }
  // Torn down here, not in the destructor, so that validation's word on it counts.
  renderer_.reset();
  imgui_.reset();
  window_.reset();
  const auto messages = context_->validationMessages();
  if (!messages.empty()) {
    fmt::print(stderr, "lll: error: {} validation message(s); see above\n", messages.size());
    return 1;
  }
  return 0;
}

void Viewer::writeScreenshot(const std::string& path) {
  writeAtomically(path, [&](const std::filesystem::path& file) {
    if (lowercaseExtension(path) == ".exr")
      writeHdr(file, renderer_->hdrImage());
    else
      writePng(file, renderer_->ldrImage());
  });
}

void Viewer::applyPendingChanges() {
  for (const std::string& path : drops_) {
    const SceneRequest before = request_;
    const std::string camera = settings_.camera;
    request_.scene = path;
    settings_.camera.clear();  // the new scene's own camera
    if (reloadScene()) {
      camera_->reset(renderer_->camera());
      message_ = fmt::format("loaded {}", path);
    } else {
      request_ = before;
      settings_.camera = camera;
    }
  }
  drops_.clear();
  if (!(request_ == appliedRequest_)) {
    if (!reloadScene()) request_ = appliedRequest_;
    return;
  }
  if (settings_ == applied_) return;
  RenderSettings onlyDisplay = settings_;
  onlyDisplay.exposure = applied_.exposure;
  onlyDisplay.ambient = applied_.ambient;
  if (onlyDisplay == applied_) {
    renderer_->setExposure(settings_.exposure, settings_.ambient);
    applied_ = settings_;
    return;
  }
  rebuildRenderer();
}

// A new scene (another file, light count, seed, GI...) and its renderer; on bad input the message
// is shown and the current scene kept.
bool Viewer::reloadScene() {
  try {
    std::vector<std::string> warnings;
    auto scene = std::make_unique<Scene>(loadScene(request_, &warnings));
    for (const std::string& w : warnings) fmt::print(stderr, "lll: warning: {}\n", w);
    particleOptions(*scene, settings_);
    auto renderer = std::make_unique<Renderer>(*context_, *scene, settings_);
    renderer_ = std::move(renderer);  // the old renderer goes before the scene it draws
    scene_ = std::move(scene);
    appliedRequest_ = request_;
    applied_ = settings_;
    time_ = request_.time;
    message_.clear();
    return true;
  } catch (const InputError& e) {
    message_ = e.what();
    fmt::print(stderr, "lll: error: {} (the current scene stays)\n", e.what());
    return false;
  }
}

bool Viewer::rebuildRenderer() {
  try {
    particleOptions(*scene_, settings_);
    auto renderer = std::make_unique<Renderer>(*context_, *scene_, settings_);
    renderer_ = std::move(renderer);
    applied_ = settings_;
    message_.clear();
    return true;
  } catch (const InputError& e) {
    message_ = e.what();
    fmt::print(stderr, "lll: error: {} (the settings stay as they were)\n", e.what());
    settings_ = applied_;
    return false;
  }
}

void Viewer::applyScriptEvents() {
  scriptInput_.look = glm::vec2(0.0f);
  scriptInput_.wheel = 0.0f;
  for (; nextEvent_ < script_.size() && script_[nextEvent_].frame <= frame_; ++nextEvent_) {
    const ScriptEvent& e = script_[nextEvent_];
    if (e.verb == "key") {
      const bool down = e.args[1] == "down";
      const std::string& k = e.args[0];
      bool* key = k == "w"   ? &scriptInput_.forward
                  : k == "s" ? &scriptInput_.back
                  : k == "a" ? &scriptInput_.left
                  : k == "d" ? &scriptInput_.right
                  : k == "e" ? &scriptInput_.up
                  : k == "q" ? &scriptInput_.down
                             : &scriptInput_.fast;
      *key = down;
    } else if (e.verb == "look") {
      scriptInput_.look += glm::vec2(scriptNumber(e, 0), scriptNumber(e, 1));
    } else if (e.verb == "wheel") {
      scriptInput_.wheel += scriptNumber(e, 0);
    } else if (e.verb == "mode") {
      camera_->setMode(e.args[0] == "orbit" ? CameraMode::Orbit : CameraMode::Fly);
    } else if (e.verb == "resize") {
      window_->resize(uint32_t(scriptNumber(e, 0)), uint32_t(scriptNumber(e, 1)));
      // The window system answers asynchronously: wait (briefly) for the new size.
      for (int i = 0; i < 100; ++i) {
        glfwWaitEventsTimeout(0.01);
        uint32_t fw = 0, fh = 0;
        window_->framebufferSize(fw, fh);
        if (fw == uint32_t(scriptNumber(e, 0)) && fh == uint32_t(scriptNumber(e, 1))) break;
      }
    } else if (e.verb == "drop") {
      drops_.push_back(e.args[0]);
    } else if (e.verb == "set") {
      applyScriptSet(e);
    } else if (e.verb == "preset-save") {
      savePreset(e.args[0]);
    } else if (e.verb == "print-camera") {
      printCamera();
    }
  }
}

void Viewer::applyScriptSet(const ScriptEvent& e) {
  const std::string& option = e.args[0];
  const std::string& value = e.args[1];
  if (option == "technique")
    settings_.technique = value;  // an unknown name fails in rebuildRenderer, shown as a message
  else if (option == "debug-view")
    settings_.debugView = value;
  else if (option == "exposure")
    settings_.exposure = std::clamp(scriptNumber(e, 1), 1e-6f, 1e6f);
  else if (option == "lights")
    request_.extraLights = uint32_t(std::clamp(scriptNumber(e, 1), 0.0f, float(gpu::kMaxLights)));
  else if (option == "tile")
    settings_.tileSize = uint32_t(scriptNumber(e, 1));
}

CameraInput Viewer::gatherInput() {
  CameraInput in = scriptInput_;
  ImGuiIO& io = ImGui::GetIO();
  GLFWwindow* w = window_->handle();
  if (!io.WantCaptureKeyboard) {
    auto down = [&](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
    in.forward |= down(GLFW_KEY_W);
    in.back |= down(GLFW_KEY_S);
    in.left |= down(GLFW_KEY_A);
    in.right |= down(GLFW_KEY_D);
    in.up |= down(GLFW_KEY_E);
    in.down |= down(GLFW_KEY_Q);
    in.fast |= down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
    // Dear ImGui 1.86 (Debian 12) indexes keys by the backend's codes: GLFW's.
    if (ImGui::IsKeyPressed(GLFW_KEY_F12, false) || ImGui::IsKeyPressed(GLFW_KEY_P, false))
      screenshotKey_ = true;
    if (ImGui::IsKeyPressed(GLFW_KEY_TAB, false)) showUi_ = !showUi_;
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) glfwSetWindowShouldClose(w, GLFW_TRUE);
  }
  glm::dvec2 cursor;
  glfwGetCursorPos(w, &cursor.x, &cursor.y);
  const bool rightButton = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
  if (rightButton && (looking_ || !io.WantCaptureMouse)) {
    if (looking_) in.look += glm::vec2(cursor - cursor_);
    looking_ = true;
  } else {
    looking_ = false;
  }
  cursor_ = cursor;
  if (!io.WantCaptureMouse) in.wheel += wheel_;
  wheel_ = 0.0f;
  return in;
}

void Viewer::printCamera() {
  cameraText_ = camera_->cameraString();
  fmt::print("camera: {}\n", cameraText_);
  std::fflush(stdout);
}

void Viewer::loadPresetForEditing() {
  edited_.reset();
  if (settings_.particles.empty()) return;
  try {
    edited_ = settings_.particlePresetJson.empty()
                  ? loadParticlePreset(settings_.particles)
                  : parseParticlePreset(settings_.particlePresetJson, settings_.particles);
  } catch (const InputError& e) {
    presetMessage_ = e.what();
  }
}

// The edited preset goes through the same JSON and the same checks as a file given to --particles.
void Viewer::applyPresetEdit() {
  const std::string text = particlePresetJson(*edited_, "edited in lll view");
  try {
    parseParticlePreset(text, "the preset editor");
    settings_.particlePresetJson = text;
    presetMessage_.clear();
  } catch (const InputError& e) {
    presetMessage_ = e.what();
  }
}

void Viewer::savePreset(const std::string& path) {
  if (!edited_) loadPresetForEditing();
  if (!edited_) {
    presetMessage_ = "no particle preset to save: choose particles first";
    fmt::print(stderr, "lll: error: preset-save {}: {}\n", path, presetMessage_);
    return;
  }
  try {
    const std::string text =
        particlePresetJson(*edited_, fmt::format("saved by lll view from {}", settings_.particles));
    parseParticlePreset(text, path);  // what --particles will say about it
    writeAtomically(path, [&](const std::filesystem::path& file) {
      std::FILE* f = std::fopen(file.c_str(), "wb");
      if (!f || std::fwrite(text.data(), 1, text.size(), f) != text.size() || std::fclose(f) != 0)
        throw InputError(fmt::format("preset: cannot write {}", path));
    });
    presetMessage_ = fmt::format("saved {}", path);
  } catch (const InputError& e) {
    presetMessage_ = e.what();
    fmt::print(stderr, "lll: error: {}\n", e.what());
  }
}

void Viewer::drawUi() {
  drawControls();
  drawTimings();
  if (editorOpen_) drawPresetEditor();
}

void Viewer::drawControls() {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(340, 520), ImGuiCond_FirstUseEver);
  ImGui::Begin("lll");
  const DeviceInfo& device = context_->info();
  ImGui::Text("%s (%s)", device.name.c_str(), device.driver.c_str());
  ImGui::Text("%s: %zu lights, %u x %u", scene_->name.c_str(), scene_->lights.size(), applied_.width,
              applied_.height);
  if (!message_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", message_.c_str());

  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
    int mode = camera_->mode() == CameraMode::Fly ? 0 : 1;
    if (ImGui::RadioButton("fly", &mode, 0)) camera_->setMode(CameraMode::Fly);
    ImGui::SameLine();
    if (ImGui::RadioButton("orbit", &mode, 1)) camera_->setMode(CameraMode::Orbit);
    float speed = camera_->speed();
    if (ImGui::DragFloat("speed m/s", &speed, 0.05f, 0.001f, 1e4f, "%.3g", ImGuiSliderFlags_Logarithmic))
      camera_->setSpeed(speed);
    std::vector<std::string> cameras;
    for (const Camera& c : scene_->cameras) cameras.push_back(c.name);
    if (cameras.empty()) cameras.push_back("overview");
    std::string picked = "pick a camera";
    if (choice("cameras", picked, cameras)) camera_->reset(resolveCamera(*scene_, picked));
    if (ImGui::Button("print --camera")) printCamera();
    if (!cameraText_.empty()) ImGui::InputText("##camera", &cameraText_, ImGuiInputTextFlags_ReadOnly);
    ImGui::TextDisabled("WASD/QE move, right mouse look, wheel speed; P screenshot, Tab hides this");
  }
  if (ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen)) {
    std::vector<std::string> names;
    for (const TechniqueInfo& t : techniques()) names.push_back(t.name);
    choice("technique", settings_.technique, names);
    choice("debug view", settings_.debugView, {"none", "heatmap", "bounds", "tiles"});
    choice("tile", settings_.tileSize, {1, 2, 4, 8, 16});
    if (settings_.technique == "lll") {
      choice("fill", settings_.lllFill, {"compute", "shells", "ray"});
      if (settings_.lllFill == "compute")
        committedUint("fill splits (0: auto)", settings_.lllFillSplits, 0, 64);
      choice("slices", settings_.lllSlices, {1, 2, 4, 8, 16, 32});
      choice("link", settings_.lllLink, {"auto", "compact", "wide"});
      choice("shade", settings_.lllShade, {"compute", "fragment"});
    }
    if (settings_.technique == "clustered") choice("cluster slices", settings_.clusterSlices, {4, 8, 16, 32});
    if (settings_.technique == "deferred") {
      choice("translucent", settings_.deferredTranslucent, {"forward", "unlit"});
      choice("anti-aliasing", settings_.antiAliasing, {"none", "edge"});
    }
    choice("surfaces", settings_.surfaces, {"visibility", "gbuffer"});
    choice("raster", settings_.raster, {"auto", "hardware", "compute"});
  }
  if (ImGui::CollapsingHeader("Lights")) {
    committedUint("random lights", request_.extraLights, 0, gpu::kMaxLights);
    committedUint("seed", request_.seed, 0, UINT32_MAX);
    float range = request_.lightRangeScale;
    ImGui::DragFloat("range scale", &range, 0.01f, 0.01f, 10.0f);
    if (ImGui::IsItemDeactivatedAfterEdit()) request_.lightRangeScale = std::clamp(range, 0.01f, 10.0f);
    if (ImGui::Checkbox("animate (orbit and bob)", &animate_) && animate_) request_.movingLights = true;
    ImGui::Text("time %.2f s", time_);
  }
  if (ImGui::CollapsingHeader("Suns")) {
    // As --sun: "x,y,z,lux[,r,g,b]", x,y,z towards the sun; a bad value keeps the scene as it was.
    std::vector<std::string> suns = request_.suns;
    bool edited = false;
    for (size_t i = 0; i < suns.size(); ++i) {
      ImGui::PushID(int(i));
      ImGui::InputText("sun", &suns[i]);
      edited |= ImGui::IsItemDeactivatedAfterEdit();
      ImGui::PopID();
    }
    if (suns.size() < 4 && ImGui::Button("add a sun")) {
      suns.push_back("0.3,1,0.2,20000");
      edited = true;
    }
    if (!suns.empty()) {
      ImGui::SameLine();
      if (ImGui::Button("remove the last")) {
        suns.pop_back();
        edited = true;
      }
    }
    if (edited) request_.suns = suns;
  }
  if (ImGui::CollapsingHeader("Shadows")) {
    choice("shadows", settings_.shadows, {"sun", "all", "none"});
    if (settings_.shadows == "all") committedUint("shadow lights", settings_.shadowLights, 0, 1024);
    choice("cascades", settings_.cascades, {1, 2, 3, 4});
    choice("cascade texels", settings_.shadowResolution, {512, 1024, 2048, 4096});
    choice("filter", settings_.shadowFilter, {"pcf", "none"});
    if (settings_.shadows == "all")
      choice("light shadow texels", settings_.shadowLightResolution, {128, 256, 512, 1024, 2048});
    choice("shadow raster", settings_.shadowRaster, {"auto", "hardware", "compute"});
  }
  if (ImGui::CollapsingHeader("Indirect light")) {
    choice("gi", request_.gi.mode, {"none", "vpl", "vpl-only"});
    committedUint("photons", request_.gi.photons, 1, gi::kMaxPhotons);
    committedUint("bounces", request_.gi.bounces, 1, gi::kMaxBounces);
    committedUint("VPL count", request_.gi.vplCount, 0, gpu::kMaxLights);
    float cutoff = request_.gi.vplCutoff;
    ImGui::DragFloat("VPL cutoff", &cutoff, 1e-5f, 1e-9f, 1.0f, "%.2e", ImGuiSliderFlags_Logarithmic);
    if (ImGui::IsItemDeactivatedAfterEdit()) request_.gi.vplCutoff = std::clamp(cutoff, 1e-9f, 1.0f);
    float range = request_.gi.vplRange;
    ImGui::DragFloat("VPL range m (0: cutoff)", &range, 0.05f, 0.0f, 1e6f);
    if (ImGui::IsItemDeactivatedAfterEdit()) request_.gi.vplRange = std::clamp(range, 0.0f, 1e6f);
  }
  if (ImGui::CollapsingHeader("Particles")) {
    std::vector<std::string> presets = {"none"};
    for (const std::string& p : builtinParticlePresets()) presets.push_back(p);
    std::string preset = settings_.particles.empty() ? "none" : settings_.particles;
    if (choice("preset", preset, presets)) {
      settings_.particles = preset == "none" ? "" : preset;
      settings_.particlePresetJson.clear();
      edited_.reset();
    }
    if (!settings_.particles.empty()) {
      committedUint("count (0: preset's)", settings_.particleCount, 0, 1000000);
      choice("lighting", settings_.particleLighting, {"pixel", "atlas", "vertex"});
      choice("render", settings_.particleRender, {"auto", "raster", "compute"});
      choice("resolution", settings_.particleResolution, {"full", "half", "quarter"});
      if (ImGui::Button("edit preset")) {
        editorOpen_ = true;
        if (!edited_) loadPresetForEditing();
      }
    }
  }
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::DragFloat("exposure", &settings_.exposure, 0.01f, 1e-3f, 1e3f, "%.3g",
                     ImGuiSliderFlags_Logarithmic);
    ImGui::DragFloat("ambient", &settings_.ambient, 0.001f, 0.0f, 10.0f);
    float scale = scale_;
    ImGui::SliderFloat("resolution scale", &scale, 0.25f, 2.0f);
    if (ImGui::IsItemDeactivatedAfterEdit()) scale_ = scale;
    if (ImGui::Button("screenshot (P)")) screenshotKey_ = true;
  }
  ImGui::End();
}

void Viewer::drawTimings() {
  ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - 308, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(300, 420), ImGuiCond_FirstUseEver);
  ImGui::Begin("GPU timings");
  std::vector<float> history(history_.begin(), history_.end());
  const float frameMs = history.empty() ? 0.0f : history.back();
  ImGui::Text("frame %.3f ms", frameMs);
  ImGui::PlotLines("##frames", history.data(), int(history.size()), 0, nullptr, 0.0f, FLT_MAX,
                   ImVec2(-1, 60));
  if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg)) {
    for (const PassTime& p : lastFrame_.passes) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(p.name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.3f", p.ms);
    }
    ImGui::EndTable();
  }
  if (ImGui::CollapsingHeader("stats") && ImGui::BeginTable("stats", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& [name, value] : stats_) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.6g", value);
    }
    ImGui::EndTable();
  }
  ImGui::End();
}

void Viewer::drawPresetEditor() {
  ImGui::SetNextWindowSize(ImVec2(360, 560), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("particle preset", &editorOpen_)) {
    ImGui::End();
    return;
  }
  if (!edited_) {
    ImGui::TextUnformatted(presetMessage_.empty() ? "no preset" : presetMessage_.c_str());
    ImGui::End();
    return;
  }
  ParticlePreset& p = *edited_;
  bool changed = false;
  auto done = [&] { changed |= ImGui::IsItemDeactivatedAfterEdit(); };
  int count = int(p.count);
  ImGui::DragInt("count", &count, 16.0f, 1, int(gpu::kMaxParticles));
  p.count = uint32_t(std::max(count, 1));
  done();
  ImGui::DragFloatRange2("lifetime s", &p.lifetimeMin, &p.lifetimeMax, 0.05f, 0.05f, 600.0f);
  done();
  int shape = int(p.shape);
  if (ImGui::Combo("emitter", &shape, "point\0disc\0sphere\0")) {
    p.shape = EmitterShape(shape);
    changed = true;
  }
  ImGui::DragFloat("emitter radius", &p.emitterRadius, 0.01f, 0.0f, 100.0f);
  done();
  ImGui::DragFloat3("emitter offset", &p.emitterOffset.x, 0.01f, -1000.0f, 1000.0f);
  done();
  ImGui::DragFloat3("direction", &p.direction.x, 0.01f, -1.0f, 1.0f);
  done();
  ImGui::DragFloat("spread deg", &p.spreadDegrees, 0.5f, 0.0f, 180.0f);
  done();
  ImGui::DragFloatRange2("speed m/s", &p.speedMin, &p.speedMax, 0.01f, 0.0f, 1000.0f);
  done();
  ImGui::DragFloat3("gravity", &p.gravity.x, 0.05f, -1000.0f, 1000.0f);
  done();
  ImGui::DragFloat("buoyancy", &p.buoyancy, 0.01f, -1000.0f, 1000.0f);
  done();
  ImGui::DragFloat("drag", &p.drag, 0.01f, 0.0f, 100.0f);
  done();
  ImGui::DragFloat("turbulence", &p.turbulenceStrength, 0.01f, 0.0f, 1000.0f);
  done();
  ImGui::DragFloat("turbulence size", &p.turbulenceSize, 0.01f, 1e-3f, 1000.0f);
  done();
  ImGui::DragFloat("turbulence speed", &p.turbulenceSpeed, 0.01f, 0.0f, 100.0f);
  done();
  ImGui::DragFloat("spin", &p.spin, 0.01f, 0.0f, 100.0f);
  done();
  int floor = int(p.floor);
  if (ImGui::Combo("floor", &floor, "none\0bounce\0kill\0")) {
    p.floor = FloorMode(floor);
    changed = true;
  }
  ImGui::DragFloat("restitution", &p.restitution, 0.01f, 0.0f, 1.0f);
  done();
  changed |= curve("size over life (m)", p.size,
                   [](float& v) { ImGui::DragFloat("##k", &v, 0.01f, 1e-4f, 100.0f); });
  ImGui::DragFloat("size variation", &p.sizeVariation, 0.01f, 0.0f, 1.0f);
  done();
  changed |= curve("colour over life", p.color, [](glm::vec3& v) { ImGui::ColorEdit3("##k", &v.x); });
  ImGui::DragFloat("colour variation", &p.colorVariation, 0.01f, 0.0f, 1.0f);
  done();
  changed |=
      curve("opacity over life", p.opacity, [](float& v) { ImGui::DragFloat("##k", &v, 0.01f, 0.0f, 1.0f); });
  changed |= curve("emission over life", p.emission,
                   [](float& v) { ImGui::DragFloat("##k", &v, 0.01f, 0.0f, 1000.0f); });
  ImGui::DragFloat("wrap", &p.wrap, 0.01f, 0.0f, 1.0f);
  done();
  ImGui::DragFloat("back", &p.back, 0.01f, 0.0f, 100.0f);
  done();
  ImGui::DragFloat("focus", &p.focus, 0.05f, 1.0f, 1000.0f);
  done();
  ImGui::DragFloat("softness m", &p.softness, 0.01f, 1e-3f, 100.0f);
  done();
  ImGui::DragFloat("additive", &p.additive, 0.01f, 0.0f, 1.0f);
  done();
  if (changed) applyPresetEdit();
  ImGui::Separator();
  ImGui::InputText("file", &presetPath_);
  if (ImGui::Button("save")) savePreset(presetPath_);
  ImGui::SameLine();
  if (ImGui::Button("load")) {
    try {
      edited_ = loadParticlePreset(presetPath_);
      applyPresetEdit();
    } catch (const InputError& e) {
      presetMessage_ = e.what();
    }
  }
  if (!presetMessage_.empty()) ImGui::TextWrapped("%s", presetMessage_.c_str());
  ImGui::End();
}

}  // namespace

int runView(const ViewJob& job) {
  Viewer viewer(job);
  return viewer.run();
}

}  // namespace lll::view
