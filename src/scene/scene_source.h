#pragma once
// Turns the SCENE argument into a Scene: a built-in name or a .gltf/.glb path; then adds the
// seeded random lights asked for with --lights.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "core/enum_names.h"
#include "gi/photons.h"
#include "scene/scene.h"

namespace lll {

// Largest --light-range-scale: beyond it every random light covers the whole default scene.
inline constexpr float kMaxLightRangeScale = 16.0f;

// --gi: none | vpl | vpl-only (the VPLs alone: the indirect light by itself).
enum class GiMode : uint8_t { None, Vpl, VplOnly };
template <>
struct EnumNames<GiMode> {
  static constexpr std::array<std::string_view, 3> names{"none", "vpl", "vpl-only"};
};

// --vpl-hierarchy: grid (the lighting grid hierarchy over the VPLs, gi/vpl_hierarchy.h) | none (one
// grid, ranges from --vpl-cutoff or --vpl-range).
enum class GiHierarchy : uint8_t { None, Grid };
template <>
struct EnumNames<GiHierarchy> {
  static constexpr std::array<std::string_view, 2> names{"none", "grid"};
};

// --gi: instant radiosity (gi/photons.h). Photons are traced from the scene's lights, the --lights
// included, and the virtual point lights they leave are added to the scene as lights.
struct GiRequest {
  GiMode mode = GiMode::None;
  uint32_t photons = gi::kDefaultPhotons;
  uint32_t bounces = gi::kDefaultBounces;
  uint32_t vplCount = gi::kDefaultVplCount;  // 0: one VPL per deposit, unmerged
  float vplCutoff = gi::kDefaultVplCutoff;
  float vplRange = 0.0f;                      // metres; 0: from the cutoff
  GiHierarchy hierarchy = GiHierarchy::Grid;  // with vplAlpha, its accuracy
  float vplAlpha = gi::kDefaultHierarchyAlpha;
  // With moving lights: their photons traced again per frame (gi/moving_vpls.h); 0: the VPLs stay
  // where the photons were first traced.
  uint32_t retrace = gi::kDefaultRetracePhotons;
  bool operator==(const GiRequest&) const = default;
};

struct SceneRequest {
  std::string scene;         // built-in name or path; empty for the default scene
  uint32_t extraLights = 0;  // --lights: scattered when the scene has none, added otherwise
  uint32_t seed = 1;
  float lightRangeScale = 1.0f;  // multiplies the ranges of the --lights lights (overdraw studies)
  // Also multiply their intensities by lightRangeScale^2, so a light's radiance at a given fraction
  // of its range is unchanged (the density study: more, smaller lights, the same exposure).
  bool scaleIntensityWithRange = false;
  // --time T / --animate: the --lights lights move (scene/light_animation.h), placed where they
  // are at `time` seconds.
  bool movingLights = false;
  float time = 0.0f;
  GiRequest gi;
  // --sun "x,y,z,lux[,r,g,b]": directional lights added to the scene's own; x,y,z point towards the
  // sun (the light travels the other way), lux its illuminance, r,g,b its linear colour (white).
  std::vector<std::string> suns;
  bool operator==(const SceneRequest&) const = default;
};

// What the photon tracing did, for the command line's report; `progress` (optional) is called with
// the fraction of photons traced.
struct IndirectLightReport {
  gi::PhotonStats stats;
  std::function<void(double)> progress;
};

// Throws InputError for an unknown name, a missing or broken file, too many lights or bad --gi
// options.
Scene loadScene(const SceneRequest& request, std::vector<std::string>* warnings = nullptr,
                IndirectLightReport* gi = nullptr);

}  // namespace lll
