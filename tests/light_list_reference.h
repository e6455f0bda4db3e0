#pragma once
// CPU references for light lists, shared by the lll and light-grid tests: lights in view space,
// the distance from a light to a tile's volume (ternary search, independent of the closed form the
// GPU uses) and sampled points of a light inside a tile's volume.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/lights.h"

namespace lll::test {

// Squared distance from c to the tile volume, minimised by ternary search over depth: f is convex
// in z (a sum of squared non-negative convex functions). Independent of the closed form the
// compute fill uses.
inline float referenceDistanceSquared(glm::vec3 c, glm::vec4 tile, float zNear, float zFar) {
  auto f = [&](float z) {
    const float dx = std::max({tile.x * z - c.x, c.x - tile.y * z, 0.0f});
    const float dy = std::max({tile.z * z - c.y, c.y - tile.w * z, 0.0f});
    return dx * dx + dy * dy + (c.z - z) * (c.z - z);
  };
  float lo = zNear, hi = zFar;
  for (int i = 0; i < 200; ++i) {
    const float a = lo + (hi - lo) / 3.0f, b = hi - (hi - lo) / 3.0f;
    (f(a) <= f(b) ? hi : lo) = (f(a) <= f(b) ? b : a);
  }
  return std::min({f(lo), f(zNear), f(zFar)});
}

struct ViewLight {
  glm::vec3 center;  // view space, z = depth in front of the eye, y up
  glm::vec3 axis;
  float range;
  float cosOuter;
  bool spot;
  bool box;
  glm::vec3 boxAxes[3];  // unit, view space
  glm::vec3 halfExtents;
};

inline glm::vec3 toViewDepth(const glm::mat4& view, const glm::vec3& direction) {
  const glm::vec3 a = glm::mat3(view) * direction;
  return {a.x, a.y, -a.z};
}

inline ViewLight toView(const Light& light, const glm::mat4& view) {
  const glm::vec3 c = glm::vec3(view * glm::vec4(light.position, 1.0f));
  ViewLight l{{c.x, c.y, -c.z},
              glm::normalize(toViewDepth(view, light.direction)),
              light.range,
              std::cos(light.outerConeAngle),
              light.type == LightType::Spot,
              light.type == LightType::Box,
              {},
              light.halfExtents};
  const glm::vec3 axes[3] = {light.boxAxisX, light.boxAxisY, glm::cross(light.boxAxisX, light.boxAxisY)};
  for (int i = 0; i < 3; ++i) l.boxAxes[i] = toViewDepth(view, axes[i]);
  return l;
}

inline bool insideLight(const ViewLight& l, glm::vec3 p, float shrink) {
  const glm::vec3 d = p - l.center;
  if (l.box) {
    for (int i = 0; i < 3; ++i)
      if (std::abs(glm::dot(d, l.boxAxes[i])) > l.halfExtents[i] * shrink) return false;
    return true;
  }
  const float dist = glm::length(d);
  if (dist > l.range * shrink) return false;
  return !l.spot || dist < 1e-6f || glm::dot(d / dist, l.axis) >= l.cosOuter + 1e-3f;
}

// Points of a tile's volume inside the light (a sampled subset of the exact intersection).
inline std::vector<glm::vec3> samplesInside(const ViewLight& l, glm::vec4 tile, float zNear, float zFar) {
  std::vector<glm::vec3> inside;
  const float z0 = std::max(zNear, l.center.z - l.range), z1 = std::min(zFar, l.center.z + l.range);
  for (int k = 0; z0 <= z1 && k <= 12; ++k) {
    const float z = z0 + (z1 - z0) * float(k) / 12.0f;
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; j <= 3; ++j) {
        const glm::vec3 p(glm::mix(tile.x, tile.y, i / 3.0f) * z, glm::mix(tile.z, tile.w, j / 3.0f) * z, z);
        if (insideLight(l, p, 0.999f)) inside.push_back(p);
      }
  }
  return inside;
}

}  // namespace lll::test
