#pragma once
// Turns the SCENE argument into a Scene: a built-in name or a .gltf/.glb path; then adds the
// seeded random lights asked for with --lights.
#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace lll {

// Largest --light-range-scale: beyond it every random light covers the whole default scene.
inline constexpr float kMaxLightRangeScale = 16.0f;

struct SceneRequest {
  std::string scene;         // built-in name or path; empty for the default scene
  uint32_t extraLights = 0;  // --lights: scattered when the scene has none, added otherwise
  uint32_t seed = 1;
  float lightRangeScale = 1.0f;  // multiplies the ranges of the --lights lights (overdraw studies)
  // Also multiply their intensities by lightRangeScale^2, so a light's radiance at a given fraction
  // of its range is unchanged (the density study: more, smaller lights, the same exposure).
  bool scaleIntensityWithRange = false;
  bool operator==(const SceneRequest&) const = default;
};

// Throws InputError for an unknown name, a missing or broken file, or too many lights.
Scene loadScene(const SceneRequest& request, std::vector<std::string>* warnings = nullptr);

}  // namespace lll
