#pragma once
// How a light's intensity falls off on the CPU, formula for formula as shaders/common/brdf.glsl
// applies it on the GPU: the photon tracer and the path-traced reference must put on a wall the
// light the renderer's direct lighting puts there.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "gi/sampling.h"
#include "scene/scene.h"

namespace lll::gi {

// Whether a light sends out light of its own: VPLs only pass on what the real lights gave them.
inline bool emitsLight(const Light& light) {
  return light.type != LightType::Vpl && light.intensity > 0.0f;
}

// Solid angle a light shines into: the whole sphere, or a spot's outer cone.
inline float emissionSolidAngle(const Light& light) {
  if (light.type == LightType::Spot) return 2.0f * kPi * (1.0f - std::cos(light.outerConeAngle));
  return 4.0f * kPi;
}

// KHR_lights_punctual's range window, the one brdf.glsl's rangeAttenuation applies.
inline float rangeWindow(float distance, float range) {
  const float r = distance / range;
  const float w = std::clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
  return w * w;
}

// GLSL's smoothstep, for brdf.glsl's hierarchyBand.
inline float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// brdf.glsl's hierarchyBand (which takes the radii's reciprocals, as the light record keeps them):
// the band of distances a VPL of the lighting grid hierarchy lights (gi/vpl_hierarchy.h).
inline float hierarchyBand(float distance, float inner, float outer) {
  const float rise = inner > 0.0f ? smoothstep(inner, 2.0f * inner, distance) : 1.0f;
  return rise * (1.0f - smoothstep(outer, 2.0f * outer, distance));
}

// brdf.glsl's boxWindow, with the axes as the Light keeps them.
inline float boxWindow(const Light& light, const glm::vec3& offset) {
  const glm::vec3 z = glm::cross(light.boxAxisX, light.boxAxisY);
  const glm::vec3 q =
      glm::vec3(glm::dot(offset, light.boxAxisX), glm::dot(offset, light.boxAxisY), glm::dot(offset, z)) /
      light.halfExtents;
  glm::vec3 w = glm::clamp(1.0f - q * q * q * q, 0.0f, 1.0f);
  w *= w;
  return w.x * w.y * w.z;
}

// KHR's spot falloff as lights.cpp encodes it for the GPU: saturate(cd * scale + offset)^2.
inline float spotFalloff(const Light& light, float cosAngle) {
  const float cosOuter = std::cos(light.outerConeAngle), cosInner = std::cos(light.innerConeAngle);
  const float scale = 1.0f / std::max(1e-4f, cosInner - cosOuter);
  const float t = std::clamp((cosAngle - cosOuter) * scale, 0.0f, 1.0f);
  return t * t;
}

}  // namespace lll::gi
