#pragma once
// shaders/common/brdf.glsl on the CPU, for the path-traced reference: the glTF 2.0 reference BRDF
// (Lambert diffuse weighted by the dielectric's Fresnel, GGX, height-correlated Smith, Schlick) and
// KHR_lights_punctual attenuation for point, spot and box lights. Kept line for line with the GLSL
// so that the reference differs from the renderer only in what it adds (shadows, indirect light).
#include <glm/glm.hpp>

#include "gi/sampling.h"
#include "scene/scene.h"

namespace lll::gi {

struct BrdfSurface {
  glm::vec3 normal{0.0f, 0.0f, 1.0f};  // unit, on the viewer's side
  glm::vec3 view{0.0f, 0.0f, 1.0f};    // unit, from the surface towards the eye
  glm::vec3 baseColor{1.0f};
  float metallic = 0.0f;
  float roughness = 1.0f;
};

// BRDF * cos(theta_l) for light arriving from unit direction l (brdf.glsl's brdfCosine).
glm::vec3 brdfCosine(const BrdfSurface& s, const glm::vec3& l);
// The same with the GGX distribution's alpha given (the Smith and Fresnel terms keep the surface's):
// a light's own lobe, as brdfCosineOver takes lightDistributionA2.
glm::vec3 brdfCosine(const BrdfSurface& s, const glm::vec3& l, float distributionAlpha);
// brdf.glsl's lightDistributionAlpha: the distribution's alpha for `light` `distance` away, a VPL's
// widened by its patch (alpha + near / (2 d), at most 1), any other light's the surface's.
float lightDistributionAlpha(const Light& light, const BrdfSurface& s, float distance);

// How much of a light's intensity reaches a point `distance` away from it, `l` the unit direction
// from the point to the light: inverse square times the light's window (range sphere, spot cone or
// box, or a VPL's cosine about its normal with 1/d^2 clamped at its near distance), zero at and
// beyond its range.
float lightAttenuation(const Light& light, const glm::vec3& l, float distance);

}  // namespace lll::gi
