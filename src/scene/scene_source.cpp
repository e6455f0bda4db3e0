#include "scene/scene_source.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

#include "core/errors.h"
#include "gi/moving_vpls.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"
#include "scene/light_animation.h"
#include "scene/lights.h"
#include "shared/limits.h"

namespace lll {

namespace {

void validateGi(const GiRequest& gi) {
  if (gi.photons < 1 || gi.photons > gi::kMaxPhotons)
    throw InputError(fmt::format("--photons {}: expected 1 to {}", gi.photons, gi::kMaxPhotons));
  if (gi.bounces < 1 || gi.bounces > gi::kMaxBounces)
    throw InputError(fmt::format("--bounces {}: expected 1 to {}", gi.bounces, gi::kMaxBounces));
  // The merge keeps the two sides of a wall apart (six normal directions per cell): fewer than six
  // VPLs cannot be met by any cell size.
  if (gi.vplCount != 0 && (gi.vplCount < 6 || gi.vplCount > gpu::kMaxLights))
    throw InputError(
        fmt::format("--vpl-count {}: expected 0 (no merging) or 6 to {}", gi.vplCount, gpu::kMaxLights));
  if (!(gi.vplCutoff >= 1e-9f && gi.vplCutoff <= 1.0f))
    throw InputError(fmt::format("--vpl-cutoff {}: expected a fraction in [1e-9, 1]", gi.vplCutoff));
  if (gi.retrace > gi::kMaxPhotons)
    throw InputError(
        fmt::format("--vpl-retrace {}: expected 0 to {} photons a frame", gi.retrace, gi::kMaxPhotons));
  if (!(gi.vplRange >= 0.0f && gi.vplRange <= 1e6f))
    throw InputError(
        fmt::format("--vpl-range {}: expected metres in [0, 1e6] (0: from --vpl-cutoff)", gi.vplRange));
  if (!(gi.vplAlpha >= gi::kMinHierarchyAlpha && gi.vplAlpha <= gi::kMaxHierarchyAlpha))
    throw InputError(fmt::format("--vpl-alpha {}: expected {} to {} (cells)", gi.vplAlpha,
                                 gi::kMinHierarchyAlpha, gi::kMaxHierarchyAlpha));
  if (gi.hierarchy == GiHierarchy::Grid && gi.vplCount == 0)
    throw InputError(
        "--vpl-count 0: the lighting grid hierarchy (--vpl-hierarchy grid, the default) needs a count to "
        "choose its finest cells; add --vpl-hierarchy none to keep every deposit as its own light");
  if (gi.hierarchy == GiHierarchy::Grid && gi.vplRange > 0.0f)
    throw InputError(
        fmt::format("--vpl-range {}: the lighting grid hierarchy (--vpl-hierarchy grid, the "
                    "default) sets every VPL's range; add --vpl-hierarchy none for a fixed range",
                    gi.vplRange));
}

// Traces the photons from the scene's lights and adds the VPLs they leave (vpl-only: instead of
// the lights). With moving lights the VPLs follow them (the scene's movingIndirect), unless
// --vpl-retrace is 0.
void addIndirectLight(Scene& scene, const SceneRequest& request, std::vector<std::string>* warnings,
                      IndirectLightReport* report) {
  gi::VplOptions options;
  options.photons = request.gi.photons;
  options.bounces = request.gi.bounces;
  options.vplCount = request.gi.vplCount;
  options.cutoff = request.gi.vplCutoff;
  options.range = request.gi.vplRange;
  options.hierarchy = request.gi.hierarchy == GiHierarchy::Grid;
  options.alpha = request.gi.vplAlpha;
  options.seed = request.seed;
  if (report) options.progress = report->progress;
  gi::PhotonStats stats;
  const bool vplOnly = request.gi.mode == GiMode::VplOnly;
  const uint64_t others = vplOnly ? 0 : scene.lights.size();
  std::vector<Light> vpls;
  if (request.movingLights && !scene.lightAnimation.empty() && request.gi.retrace > 0) {
    scene.movingIndirect.vpls = std::make_shared<gi::MovingVpls>(
        scene, options, request.gi.retrace,
        uint32_t(gpu::kMaxLights - std::min<uint64_t>(others, gpu::kMaxLights)), std::vector<gi::VplLevel>{},
        &stats);
    vpls = scene.movingIndirect.vpls->vpls();
    scene.movingIndirect.clone = &gi::cloneMovingVpls;
    scene.movingIndirect.first = uint32_t(others);
  } else {
    vpls = gi::makeVirtualPointLights(scene, options, &stats);
  }
  if (report) report->stats = stats;
  if (stats.vpls == 0 && warnings)
    warnings->push_back(
        fmt::format("--gi {}: no photon landed on a surface that reflects light ({} lights, {} photons): "
                    "no virtual point lights",
                    request.gi.mode, scene.lights.size(), request.gi.photons));
  if (vplOnly) {
    scene.lights.clear();
    scene.lightAnimation = {};  // the lights that moved are gone (their VPLs may still follow them)
  }
  if (scene.lights.size() + vpls.size() > gpu::kMaxLights)
    throw InputError(
        fmt::format("--gi {}: {} virtual point lights and {} lights exceed the {} supported; lower "
                    "--vpl-count",
                    request.gi.mode, vpls.size(), scene.lights.size(), gpu::kMaxLights));
  scene.lights.insert(scene.lights.end(), vpls.begin(), vpls.end());
}

// "x,y,z,lux[,r,g,b]" as --sun takes it.
DirectionalLight parseSun(const std::string& text) {
  std::vector<float> values;
  size_t begin = 0;
  while (begin <= text.size()) {
    const size_t end = std::min(text.find(',', begin), text.size());
    const std::string field = text.substr(begin, end - begin);
    char* stop = nullptr;
    const float value = std::strtof(field.c_str(), &stop);
    if (field.empty() || stop != field.c_str() + field.size() || !std::isfinite(value))
      throw InputError(fmt::format("--sun {}: '{}' is not a finite number", text, field));
    values.push_back(value);
    begin = end + 1;
  }
  if (values.size() != 4 && values.size() != 7)
    throw InputError(fmt::format("--sun {}: expected x,y,z,lux or x,y,z,lux,r,g,b ({} numbers given)", text,
                                 values.size()));
  const glm::vec3 towards(values[0], values[1], values[2]);
  if (!(glm::length(towards) > 1e-6f))
    throw InputError(fmt::format("--sun {}: the direction towards the sun has no length", text));
  DirectionalLight sun;
  sun.name = "--sun " + text;
  sun.direction = -glm::normalize(towards);
  sun.illuminance = values[3];
  if (!(sun.illuminance >= 0.0f && sun.illuminance <= kMaxLightIntensity))
    throw InputError(fmt::format("--sun {}: illuminance {} lux is outside [0, {:g}]", text, values[3],
                                 kMaxLightIntensity));
  if (values.size() == 7) {
    sun.color = glm::vec3(values[4], values[5], values[6]);
    if (glm::any(glm::lessThan(sun.color, glm::vec3(0.0f))) ||
        glm::any(glm::greaterThan(sun.color, glm::vec3(1.0f))))
      throw InputError(fmt::format("--sun {}: colour components must lie in [0, 1]", text));
  }
  return sun;
}

void addSuns(Scene& scene, const std::vector<std::string>& suns) {
  for (const std::string& text : suns) scene.directionalLights.push_back(parseSun(text));
  if (scene.directionalLights.size() > gpu::kMaxDirectionalLights)
    throw InputError(
        fmt::format("--sun: the scene would have {} directional lights; at most {} are supported",
                    scene.directionalLights.size(), gpu::kMaxDirectionalLights));
}

}  // namespace

Scene loadScene(const SceneRequest& request, std::vector<std::string>* warnings, IndirectLightReport* gi) {
  validateGi(request.gi);
  const std::string name = request.scene.empty() ? std::string(kDefaultSceneName) : request.scene;
  Scene scene;
  if (auto builtin = makeBuiltinScene(name)) {
    scene = std::move(*builtin);
  } else {
    const std::filesystem::path path(name);
    const std::string ext = path.extension().string();
    std::error_code error;  // a name too long for the file system is an error, not an exception
    if (!std::filesystem::exists(path, error) && ext != ".gltf" && ext != ".glb") {
      std::string names;
      for (const BuiltinSceneInfo& info : builtinScenes()) names += (names.empty() ? "" : ", ") + info.name;
      throw InputError(fmt::format(
          "scene '{}': neither a built-in scene ({}) nor an existing .gltf/.glb file", name, names));
    }
    LoadReport report;
    scene = loadGltf(path, &report);
    if (warnings) warnings->insert(warnings->end(), report.warnings.begin(), report.warnings.end());
    // A valid glTF may hold only lights or cameras; rendering one gives a black image.
    if (scene.triangleCount() == 0)
      throw InputError(fmt::format(
          "{}: has nothing to draw: no node of its scene places a mesh with a triangle", path.string()));
  }
  if (uint64_t(scene.lights.size()) + request.extraLights > gpu::kMaxLights)
    throw InputError(fmt::format("--lights {}: the scene would have {} lights; at most {} are supported",
                                 request.extraLights, scene.lights.size() + request.extraLights,
                                 gpu::kMaxLights));
  if (!(request.lightRangeScale > 0.0f && request.lightRangeScale <= kMaxLightRangeScale))
    throw InputError(fmt::format("--light-range-scale {}: expected a factor in (0, {}]",
                                 request.lightRangeScale, kMaxLightRangeScale));
  if (request.extraLights > 0) {
    const Bounds bounds = scene.worldBounds();
    if (!bounds.valid())
      throw InputError(fmt::format("scene '{}': has no geometry to place --lights in", name));
    const size_t first = scene.lights.size();
    scatterRandomLights(scene.lights, bounds, request.extraLights, request.seed);
    const float intensityScale =
        request.scaleIntensityWithRange ? request.lightRangeScale * request.lightRangeScale : 1.0f;
    for (size_t i = first; i < scene.lights.size(); ++i) {
      scene.lights[i].range *= request.lightRangeScale;
      scene.lights[i].intensity *= intensityScale;
    }
    if (request.movingLights)
      scene.lightAnimation =
          makeLightAnimation(scene.lights, uint32_t(first), request.extraLights, bounds, request.seed);
  }
  if (request.movingLights) {
    placeLightsAt(scene.lights, scene.lightAnimation, request.time);  // checks the time
    if (scene.lightAnimation.empty() && warnings)
      warnings->push_back("--time/--animate move the --lights lights, and there are none: nothing moves");
  }
  addSuns(scene, request.suns);
  if (request.gi.mode != GiMode::None) addIndirectLight(scene, request, warnings, gi);
  return scene;
}

}  // namespace lll
