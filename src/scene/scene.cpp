#include "scene/scene.h"

namespace lll {

Bounds Scene::worldBounds() const {
  Bounds bounds;
  for (const Instance& instance : instances) {
    for (const Primitive& primitive : meshes[instance.mesh].primitives) {
      for (uint32_t i = 0; i < primitive.indexCount; ++i) {
        const Vertex& v = vertices[primitive.vertexOffset + indices[primitive.firstIndex + i]];
        bounds.expand(glm::vec3(instance.transform * glm::vec4(v.position, 1.0f)));
      }
    }
  }
  return bounds;
}

uint64_t Scene::triangleCount() const {
  uint64_t triangles = 0;
  for (const Instance& instance : instances) {
    for (const Primitive& primitive : meshes[instance.mesh].primitives) triangles += primitive.indexCount / 3;
  }
  return triangles;
}

}  // namespace lll
