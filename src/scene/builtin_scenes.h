#pragma once
// Scenes made in code, so that lll runs and benchmarks with no asset files: the default "atrium"
// (a two-storey arcaded courtyard with ~100 coloured lights), ThreeL's full-screen-light
// benchmarks on the same geometry, and analytic test scenes (one plane, one light).
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace lll {

struct BuiltinSceneInfo {
  std::string name;
  std::string description;
};

// Every built-in scene, the default first, for `lll scenes`.
std::vector<BuiltinSceneInfo> builtinScenes();

// Builds the named scene; nullopt when no built-in scene has that name. The same name gives the
// same scene on every machine.
std::optional<Scene> makeBuiltinScene(const std::string& name);

inline constexpr const char* kDefaultSceneName = "atrium";

}  // namespace lll
