#pragma once
// What every scene the glTF loader returns must satisfy, whatever file it was given: nothing in it
// can make the renderer read out of bounds or shade a NaN. Shared by the fuzz target (fuzz/) and
// the replay of the inputs that once failed (tests/test_fuzz_regressions.cpp). Header-only: the
// fuzz build compiles no test library.
#include <cmath>
#include <glm/glm.hpp>
#include <string>

#include "scene/lights.h"
#include "scene/scene.h"

namespace lll::test {

inline bool finite(float v) {
  return std::isfinite(v);
}
template <int N>
bool finite(const glm::vec<N, float>& v) {
  for (int i = 0; i < N; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// The first broken invariant, described; empty when the scene is sound.
inline std::string sceneInvariantViolation(const Scene& scene) {
  for (size_t i = 0; i < scene.vertices.size(); ++i) {
    const Vertex& v = scene.vertices[i];
    if (!finite(v.position) || !finite(v.normal) || !finite(v.uv))
      return "vertex " + std::to_string(i) + " is not finite";
    if (!(glm::length(v.normal) > 1e-7f)) return "vertex " + std::to_string(i) + " has a zero normal";
  }
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    for (const Primitive& p : scene.meshes[m].primitives) {
      if (p.indexCount % 3 != 0 || uint64_t(p.firstIndex) + p.indexCount > scene.indices.size())
        return "mesh " + std::to_string(m) + " has a primitive outside the index array";
      if (p.material >= scene.materials.size()) return "mesh " + std::to_string(m) + " has no such material";
      for (uint32_t k = 0; k < p.indexCount; ++k)
        if (uint64_t(p.vertexOffset) + scene.indices[p.firstIndex + k] >= scene.vertices.size())
          return "mesh " + std::to_string(m) + " indexes past the vertex array";
    }
  }
  for (const Material& m : scene.materials) {
    if (!finite(m.baseColorFactor) || !finite(m.emissiveFactor) || !finite(m.emissiveStrength) ||
        !finite(m.metallic) || !finite(m.roughness) || !finite(m.normalScale) ||
        !finite(m.occlusionStrength) || !finite(m.alphaCutoff))
      return "material '" + m.name + "' has a factor that is not finite";
    for (int c = 0; c < 3; ++c)
      if (!(double(m.emissiveFactor[c]) * m.emissiveStrength <= kMaxEmissiveStrength))
        return "material '" + m.name + "' emits more than the shading takes";
    for (int texture : {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture, m.emissiveTexture,
                        m.occlusionTexture})
      if (texture >= int(scene.textures.size())) return "material '" + m.name + "' has no such texture";
  }
  for (const Texture& t : scene.textures)
    if (t.rgba.size() != size_t(t.width) * t.height * 4 || t.width == 0 || t.height == 0)
      return "texture '" + t.name + "' has the wrong pixel count";
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    if (instance.mesh >= scene.meshes.size()) return "instance " + std::to_string(i) + " has no such mesh";
    for (int c = 0; c < 4; ++c)
      if (!finite(instance.transform[c]))
        return "instance " + std::to_string(i) + " has a transform not finite";
  }
  const Bounds bounds = scene.worldBounds();
  if (bounds.valid() &&
      (!finite(bounds.min) || !finite(bounds.max) ||
       glm::max(glm::max(-bounds.min.x, -bounds.min.y), -bounds.min.z) > kMaxWorldCoordinate ||
       glm::max(glm::max(bounds.max.x, bounds.max.y), bounds.max.z) > kMaxWorldCoordinate))
    return "the scene's bounds are beyond what 32-bit arithmetic takes";
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    if (!finite(l.position) || !finite(l.direction) || !finite(l.color) || !finite(l.intensity) ||
        !finite(l.range) || !(l.range > 0.0f) || !(l.intensity >= 0.0f && l.intensity <= kMaxLightIntensity))
      return "light " + std::to_string(i) + " is not finite, negative or too bright";
  }
  for (const Camera& c : scene.cameras) {
    if (!finite(c.eye) || !finite(c.target) || !finite(c.up) || !(c.yfov > 0.0f && c.yfov < 3.1416f))
      return "camera '" + c.name + "' is not finite or has no field of view";
  }
  return {};
}

}  // namespace lll::test
