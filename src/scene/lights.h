#pragma once
// Light helpers shared by every scene source: seeded random lights, the finite range given to a
// glTF light that has none, and the conversion to the GPU layout.
#include <cstdint>
#include <vector>

#include "scene/scene.h"
#include "shared/gpu_types.h"

namespace lll {

// Irradiance (W/m^2 for a 1 cd, white light) under which a light without a glTF range is cut off.
// KHR_lights_punctual lets an unbounded light reach infinity; a tiled renderer needs a finite
// volume. At this threshold the clipped tail is invisible after tonemapping at exposure 1.
inline constexpr float kUnboundedLightCutoff = 1e-3f;

// The brightest light (cd) and emission a scene may hold. Shading multiplies them by up to 1e4
// (1/d^2 with d >= 1 cm), a specular peak (~1e4) and the exposure (<= 1e6): beyond this the 32-bit
// product overflows, and infinity times a zero somewhere is a NaN pixel.
inline constexpr float kMaxLightIntensity = 1e20f;
inline constexpr float kMaxEmissiveStrength = 1e20f;

// Range for a glTF light with no "range": where intensity * max(colour) / d^2 falls to the cutoff.
float rangeForUnboundedLight(float intensity, const glm::vec3& color);

// Adds `count` point lights at seeded random positions inside `bounds`, with saturated random
// hues and ranges scaled to the scene (a few percent to ~15% of its diagonal), bright enough to
// read at exposure 1. The same seed gives the same lights on every machine.
void scatterRandomLights(std::vector<Light>& lights, const Bounds& bounds, uint32_t count, uint32_t seed);

// A box light centred at `center` with orthonormalised axes (x, then y made orthogonal to it) and
// half extents; its range is set to the box's bounding radius.
Light makeBoxLight(const glm::vec3& center, const glm::vec3& axisX, const glm::vec3& axisY,
                   const glm::vec3& halfExtents, const glm::vec3& color, float intensity);

gpu::GpuLight toGpuLight(const Light& light);

}  // namespace lll
