// lll view's Dear ImGui panels: the controls, the GPU timings and the particle preset editor. Each
// edits the viewer's requested scene and settings; Viewer::applyPendingChanges applies them between
// frames.
#include <fmt/format.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cfloat>
#include <type_traits>

#include "view/viewer_app.h"

namespace lll::view {

namespace {

// A combo box over choices (names or numbers); true when the value changed.
template <typename T>
bool choice(const char* label, T& value, const std::vector<T>& options) {
  bool changed = false;
  if (ImGui::BeginCombo(label, fmt::format("{}", value).c_str())) {
    for (const T& option : options) {
      const bool selected = option == value;
      if (ImGui::Selectable(fmt::format("{}", option).c_str(), selected) && !selected) {
        value = option;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// A combo box over every value of an option, by name.
template <NamedEnum E>
bool choice(const char* label, E& value) {
  return choice(label, value, enumValues<E>());
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
  if (keys.size() < gpu::kMaxCurveKeys && ImGui::SmallButton("+")) {
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

// One row of a two-column table: a name and its value.
void tableRow(const std::string& name, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(name.c_str());
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(value.c_str());
}

}  // namespace

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
    choice("debug view", settings_.debugView);
    choice("tile (0: the technique's)", settings_.tileSize, {0, 1, 2, 4, 8, 16});
    if (settings_.technique == "lll") {
      choice("fill", settings_.lllFill);
      if (settings_.lllFill == LllFill::Compute)
        committedUint("fill splits (0: auto)", settings_.lllFillSplits, 0, 64);
      choice("slices", settings_.lllSlices, {1, 2, 4, 8, 16, 32});
      choice("link", settings_.lllLink);
      choice("records", settings_.lllRecords);
      choice("shade", settings_.lllShade);
    }
    if (settings_.technique == "clustered") choice("cluster slices", settings_.clusterSlices, {4, 8, 16, 32});
    if (settings_.technique == "deferred") {
      choice("translucent", settings_.deferredTranslucent);
      choice("anti-aliasing", settings_.antiAliasing);
    }
    choice("surfaces", settings_.surfaces);
    choice("glass", settings_.glass);
    choice("raster", settings_.raster);
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
    choice("shadows", settings_.shadows);
    if (settings_.shadows == ShadowMode::All) committedUint("shadow lights", settings_.shadowLights, 0, 1024);
    choice("cascades", settings_.cascades, {1, 2, 3, 4});
    choice("cascade texels", settings_.shadowResolution, {512, 1024, 2048, 4096});
    choice("filter", settings_.shadowFilter);
    if (settings_.shadows == ShadowMode::All)
      choice("light shadow texels", settings_.shadowLightResolution, {128, 256, 512, 1024, 2048});
    choice("shadow raster", settings_.shadowRaster);
  }
  if (ImGui::CollapsingHeader("Indirect light")) {
    choice("gi", request_.gi.mode);
    committedUint("photons", request_.gi.photons, 1, gi::kMaxPhotons);
    committedUint("bounces", request_.gi.bounces, 1, gi::kMaxBounces);
    committedUint("VPL count", request_.gi.vplCount, 0, gpu::kMaxLights);
    // The lighting grid hierarchy (gi/vpl_hierarchy.h): its levels' bands replace cutoff and range.
    choice("VPL hierarchy", request_.gi.hierarchy);
    if (request_.gi.hierarchy == GiHierarchy::Grid) {
      float alpha = request_.gi.vplAlpha;
      ImGui::DragFloat("hierarchy alpha", &alpha, 0.05f, gi::kMinHierarchyAlpha, gi::kMaxHierarchyAlpha,
                       "%.2f");
      if (ImGui::IsItemDeactivatedAfterEdit())
        request_.gi.vplAlpha = std::clamp(alpha, gi::kMinHierarchyAlpha, gi::kMaxHierarchyAlpha);
    }
    if (request_.gi.hierarchy != GiHierarchy::Grid) {  // the hierarchy's bands set the ranges
      float cutoff = request_.gi.vplCutoff;
      ImGui::DragFloat("VPL cutoff", &cutoff, 1e-5f, 1e-9f, 1.0f, "%.2e", ImGuiSliderFlags_Logarithmic);
      if (ImGui::IsItemDeactivatedAfterEdit()) request_.gi.vplCutoff = std::clamp(cutoff, 1e-9f, 1.0f);
      float range = request_.gi.vplRange;
      ImGui::DragFloat("VPL range m (0: cutoff)", &range, 0.05f, 0.0f, 1e6f);
      if (ImGui::IsItemDeactivatedAfterEdit()) request_.gi.vplRange = std::clamp(range, 0.0f, 1e6f);
    }
    // Each pixel of a KxK block evaluates a (K*K)th of the VPLs (render/interleaved_vpls.h).
    choice("VPL interleave K", settings_.vplInterleave, {1u, 2u, 3u, 4u});
    // With moving lights: the photons traced again each frame (gi/moving_vpls.h; 0: the VPLs stay).
    committedUint("re-traced photons a frame", request_.gi.retrace, 0, gi::kMaxPhotons);
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
      choice("lighting", settings_.particleLighting);
      choice("render", settings_.particleRender);
      choice("resolution", settings_.particleResolution);
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
    for (const PassTime& p : lastFrame_.passes) tableRow(p.name, fmt::format("{:.3f}", p.ms));
    ImGui::EndTable();
  }
  if (ImGui::CollapsingHeader("stats") && ImGui::BeginTable("stats", 2, ImGuiTableFlags_RowBg)) {
    for (const auto& [name, value] : stats_) tableRow(name, fmt::format("{:.6g}", value));
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
  // Each field applies when its widget is let go (a drag would otherwise restart the emitter at
  // every step).
  auto drag = [&](const char* label, float& v, float speed, float lo, float hi) {
    ImGui::DragFloat(label, &v, speed, lo, hi);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  };
  auto drag3 = [&](const char* label, glm::vec3& v, float speed, float lo, float hi) {
    ImGui::DragFloat3(label, &v.x, speed, lo, hi);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  };
  auto range = [&](const char* label, float& lo, float& hi, float speed, float min, float max) {
    ImGui::DragFloatRange2(label, &lo, &hi, speed, min, max);
    changed |= ImGui::IsItemDeactivatedAfterEdit();
  };
  auto pick = [&](const char* label, auto& value, const char* names) {
    int index = int(value);
    if (ImGui::Combo(label, &index, names)) {
      value = std::remove_reference_t<decltype(value)>(index);
      changed = true;
    }
  };
  int count = int(p.count);
  ImGui::DragInt("count", &count, 16.0f, 1, int(gpu::kMaxParticles));
  p.count = uint32_t(std::max(count, 1));
  changed |= ImGui::IsItemDeactivatedAfterEdit();
  range("lifetime s", p.lifetimeMin, p.lifetimeMax, 0.05f, 0.05f, 600.0f);
  pick("emitter", p.shape, "point\0disc\0sphere\0");
  drag("emitter radius", p.emitterRadius, 0.01f, 0.0f, 100.0f);
  drag3("emitter offset", p.emitterOffset, 0.01f, -1000.0f, 1000.0f);
  drag3("direction", p.direction, 0.01f, -1.0f, 1.0f);
  drag("spread deg", p.spreadDegrees, 0.5f, 0.0f, 180.0f);
  range("speed m/s", p.speedMin, p.speedMax, 0.01f, 0.0f, 1000.0f);
  drag3("gravity", p.gravity, 0.05f, -1000.0f, 1000.0f);
  drag("buoyancy", p.buoyancy, 0.01f, -1000.0f, 1000.0f);
  drag("drag", p.drag, 0.01f, 0.0f, 100.0f);
  drag("turbulence", p.turbulenceStrength, 0.01f, 0.0f, 1000.0f);
  drag("turbulence size", p.turbulenceSize, 0.01f, 1e-3f, 1000.0f);
  drag("turbulence speed", p.turbulenceSpeed, 0.01f, 0.0f, 100.0f);
  drag("spin", p.spin, 0.01f, 0.0f, 100.0f);
  pick("floor", p.floor, "none\0bounce\0kill\0");
  drag("restitution", p.restitution, 0.01f, 0.0f, 1.0f);
  changed |= curve("size over life (m)", p.size,
                   [](float& v) { ImGui::DragFloat("##k", &v, 0.01f, 1e-4f, 100.0f); });
  drag("size variation", p.sizeVariation, 0.01f, 0.0f, 1.0f);
  changed |= curve("colour over life", p.color, [](glm::vec3& v) { ImGui::ColorEdit3("##k", &v.x); });
  drag("colour variation", p.colorVariation, 0.01f, 0.0f, 1.0f);
  changed |=
      curve("opacity over life", p.opacity, [](float& v) { ImGui::DragFloat("##k", &v, 0.01f, 0.0f, 1.0f); });
  changed |= curve("emission over life", p.emission,
                   [](float& v) { ImGui::DragFloat("##k", &v, 0.01f, 0.0f, 1000.0f); });
  drag("wrap", p.wrap, 0.01f, 0.0f, 1.0f);
  drag("back", p.back, 0.01f, 0.0f, 100.0f);
  drag("focus", p.focus, 0.05f, 1.0f, 1000.0f);
  drag("softness m", p.softness, 0.01f, 1e-3f, 100.0f);
  drag("additive", p.additive, 0.01f, 0.0f, 1.0f);
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

}  // namespace lll::view
