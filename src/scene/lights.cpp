#include "scene/lights.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace lll {

float rangeForUnboundedLight(float intensity, const glm::vec3& color) {
  const float peak = std::max(intensity * std::max(color.r, std::max(color.g, color.b)), 0.0f);
  return std::sqrt(peak / kUnboundedLightCutoff);
}

namespace {

glm::vec3 hueToRgb(float hue) {
  const glm::vec3 k = glm::abs(glm::fract(glm::vec3(hue) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f -
                               glm::vec3(3.0f));
  return glm::clamp(k - glm::vec3(1.0f), 0.0f, 1.0f);
}

}  // namespace

void scatterRandomLights(std::vector<Light>& lights, const Bounds& bounds, uint32_t count, uint32_t seed) {
  // std::mt19937 output is specified by the standard; the distributions are not, so map the raw
  // 32-bit values ourselves to keep scenes identical across standard libraries.
  std::mt19937 rng(seed);
  auto uniform = [&rng](float lo, float hi) {
    return lo + (hi - lo) * float(rng() >> 8) * (1.0f / 16777216.0f);
  };
  const glm::vec3 extent = bounds.extent();
  const float diagonal = glm::length(extent);
  for (uint32_t i = 0; i < count; ++i) {
    Light light;
    light.type = LightType::Point;
    light.position = bounds.min + glm::vec3(uniform(0, 1), uniform(0, 1), uniform(0, 1)) * extent;
    light.color = glm::mix(glm::vec3(1.0f), hueToRgb(uniform(0, 1)), 0.85f);
    light.range = diagonal * uniform(0.03f, 0.12f);
    // Radiance at a third of the range is about 0.6 whatever the range: lights of every size read.
    light.intensity =
        0.6f * (light.range * light.range / 9.0f) / std::pow(1.0f - std::pow(1.0f / 3.0f, 4.0f), 2.0f);
    lights.push_back(light);
  }
}

Light makeBoxLight(const glm::vec3& center, const glm::vec3& axisX, const glm::vec3& axisY,
                   const glm::vec3& halfExtents, const glm::vec3& color, float intensity) {
  Light l;
  l.type = LightType::Box;
  l.position = center;
  l.boxAxisX = glm::normalize(axisX);
  l.boxAxisY = glm::normalize(axisY - l.boxAxisX * glm::dot(axisY, l.boxAxisX));
  l.halfExtents = halfExtents;
  l.range = glm::length(halfExtents);
  l.color = color;
  l.intensity = intensity;
  return l;
}

gpu::GpuLight toGpuLight(const Light& light) {
  gpu::GpuLight g{};
  g.positionRange = glm::vec4(light.position, light.range);
  g.colorIntensity = glm::vec4(light.color, light.intensity);
  if (light.type == LightType::Box) {
    // Axes over half extents: the shading's box coordinates are plain dot products.
    const glm::vec3 h = light.halfExtents;
    g.directionType = glm::vec4(light.boxAxisX / h.x, float(gpu::kLightBox));
    g.spotParams = glm::vec4(light.boxAxisY / h.y, h.x * h.y / h.z);
    return g;
  }
  if (light.type == LightType::Vpl) {
    g.directionType = glm::vec4(glm::normalize(light.direction), float(gpu::kLightVpl));
    // The band's radii as reciprocals (0: none), so that shading multiplies (common/brdf.glsl).
    const auto inverse = [](float r) { return r > 0.0f ? 1.0f / r : 0.0f; };
    g.spotParams = glm::vec4(light.nearDistance, inverse(light.bandInner), inverse(light.bandOuter), 0.0f);
    return g;
  }
  const uint32_t type = light.type == LightType::Spot ? gpu::kLightSpot : gpu::kLightPoint;
  g.directionType = glm::vec4(glm::normalize(light.direction), float(type));
  // KHR_lights_punctual's spot falloff, precomputed: smooth = saturate((cd - cos outer) * scale)^2.
  // w is the light's shadow views (shadows/local_shadows.h): 0, none, until a frame gives it some.
  const float cosOuter = std::cos(light.outerConeAngle);
  const float cosInner = std::cos(light.innerConeAngle);
  const float scale = 1.0f / std::max(1e-4f, cosInner - cosOuter);
  g.spotParams = glm::vec4(cosOuter, cosInner, scale, 0.0f);
  return g;
}

}  // namespace lll
