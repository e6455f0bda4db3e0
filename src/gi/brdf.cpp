#include "gi/brdf.h"

#include <algorithm>
#include <cmath>

#include "gi/light_falloff.h"

namespace lll::gi {
namespace {

constexpr float kDielectricF0 = 0.04f;

glm::vec3 halfVector(const glm::vec3& l, const glm::vec3& v) {
  const glm::vec3 h = l + v;
  return h / std::sqrt(std::max(glm::dot(h, h), 1e-12f));
}

float distributionGgx(float nDotH, float alphaRoughness) {
  const float a2 = alphaRoughness * alphaRoughness;
  const float d = nDotH * nDotH * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

float visibilitySmithGgxCorrelated(float nDotL, float nDotV, float alphaRoughness) {
  const float a2 = alphaRoughness * alphaRoughness;
  const float ggxV = nDotL * std::sqrt(nDotV * nDotV * (1.0f - a2) + a2);
  const float ggxL = nDotV * std::sqrt(nDotL * nDotL * (1.0f - a2) + a2);
  const float sum = ggxV + ggxL;
  return sum > 0.0f ? 0.5f / sum : 0.0f;
}

glm::vec3 fresnelSchlick(const glm::vec3& f0, float vDotH) {
  return f0 + (1.0f - f0) * std::pow(1.0f - vDotH, 5.0f);
}

float surfaceAlpha(const BrdfSurface& s) {
  return std::max(s.roughness * s.roughness, 1e-3f);
}

}  // namespace

glm::vec3 brdfCosine(const BrdfSurface& s, const glm::vec3& l) {
  return brdfCosine(s, l, surfaceAlpha(s));
}

glm::vec3 brdfCosine(const BrdfSurface& s, const glm::vec3& l, float distributionAlpha) {
  const float nDotL = glm::dot(s.normal, l);
  if (nDotL <= 0.0f) return glm::vec3(0.0f);
  const float nDotV = std::max(glm::dot(s.normal, s.view), 1e-4f);
  const glm::vec3 h = halfVector(l, s.view);
  const float nDotH = std::max(glm::dot(s.normal, h), 0.0f);
  const float vDotH = std::clamp(glm::dot(s.view, h), 0.0f, 1.0f);
  const float alphaRoughness = surfaceAlpha(s);
  const glm::vec3 f0 = glm::mix(glm::vec3(kDielectricF0), s.baseColor, s.metallic);
  const float dielectricFresnel = fresnelSchlick(glm::vec3(kDielectricF0), vDotH).x;
  const glm::vec3 diffuse = (1.0f - s.metallic) * (1.0f - dielectricFresnel) * s.baseColor / kPi;
  const glm::vec3 specular = fresnelSchlick(f0, vDotH) * distributionGgx(nDotH, distributionAlpha) *
                             visibilitySmithGgxCorrelated(nDotL, nDotV, alphaRoughness);
  return (diffuse + specular) * nDotL;
}

float lightDistributionAlpha(const Light& light, const BrdfSurface& s, float distance) {
  const float alpha = surfaceAlpha(s);
  if (light.type != LightType::Vpl) return alpha;
  return std::min(alpha + 0.5f * light.nearDistance / std::max(distance, 1e-6f), 1.0f);
}

float lightAttenuation(const Light& light, const glm::vec3& l, float distance) {
  if (!(distance < light.range)) return 0.0f;
  if (light.type == LightType::Vpl) {
    const float clamped = std::max(distance, light.nearDistance);
    const float window = light.bandOuter > 0.0f ? hierarchyBand(distance, light.bandInner, light.bandOuter)
                                                : rangeWindow(clamped, light.range);
    return window / std::max(clamped * clamped, 1e-4f) * std::max(glm::dot(light.direction, -l), 0.0f);
  }
  const float inverseSquare = 1.0f / std::max(distance * distance, 1e-4f);
  if (light.type == LightType::Box) return boxWindow(light, -l * distance) * inverseSquare;
  const float spot = light.type == LightType::Spot
                         ? spotFalloff(light, glm::dot(glm::normalize(light.direction), -l))
                         : 1.0f;
  return rangeWindow(distance, light.range) * inverseSquare * spot;
}

}  // namespace lll::gi
