#include "view/viewer.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "view/viewer_app.h"

namespace lll::view {

namespace {

constexpr size_t kHistoryFrames = 240;  // the rolling frame-time graph

void checkImguiResult(VkResult result) {
  if (result != VK_SUCCESS) throwVulkanError("Dear ImGui's Vulkan backend", __FILE__, __LINE__, result);
}

}  // namespace

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

Viewer::~Viewer() = default;

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
    if (lastFrame && job_.screenshot) writeScreenshot(*job_.screenshot);
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
    if (rebuild(true)) {
      camera_->reset(renderer_->camera());
      message_ = fmt::format("loaded {}", path);
    } else {
      request_ = before;
      settings_.camera = camera;
    }
  }
  drops_.clear();
  if (!(request_ == appliedRequest_)) {
    if (!rebuild(true)) request_ = appliedRequest_;
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
  rebuild(false);
}

// A new scene (another file, light count, seed, suns, GI...) or new settings: a new renderer.
// Bad input (the Renderer checks the settings and the particle preset) leaves what was there.
bool Viewer::rebuild(bool reload) {
  try {
    std::unique_ptr<Scene> scene;
    if (reload) {
      std::vector<std::string> warnings;
      scene = std::make_unique<Scene>(loadScene(request_, &warnings));
      for (const std::string& w : warnings) fmt::print(stderr, "lll: warning: {}\n", w);
    }
    auto renderer = std::make_unique<Renderer>(*context_, scene ? *scene : *scene_, settings_);
    renderer_ = std::move(renderer);  // the old renderer goes before the scene it draws
    if (scene) {
      scene_ = std::move(scene);
      appliedRequest_ = request_;
      time_ = request_.time;
    }
    applied_ = settings_;
    message_.clear();
    return true;
  } catch (const InputError& e) {
    message_ = e.what();
    fmt::print(stderr, "lll: error: {} ({})\n", e.what(),
               reload ? "the current scene stays" : "the settings stay as they were");
    if (!reload) settings_ = applied_;
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
    settings_.technique = value;  // an unknown name fails in rebuild(), shown as a message
  else if (option == "debug-view")
    settings_.debugView = enumFromName<DebugView>(value).value();  // checked by parseInputScript
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
    edited_ = settingsParticlePreset(settings_);
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

int runView(const ViewJob& job) {
  Viewer viewer(job);
  return viewer.run();
}

}  // namespace lll::view
