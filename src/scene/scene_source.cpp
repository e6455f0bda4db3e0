#include "scene/scene_source.h"

#include <fmt/format.h>

#include <filesystem>

#include "scene/builtin_scenes.h"
#include "scene/errors.h"
#include "scene/gltf_loader.h"
#include "scene/lights.h"
#include "shared/limits.h"

namespace lll {

Scene loadScene(const SceneRequest& request, std::vector<std::string>* warnings) {
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
  }
  return scene;
}

}  // namespace lll
