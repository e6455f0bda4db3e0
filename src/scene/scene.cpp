#include "scene/scene.h"

namespace lll {

Bounds transformBounds(const Bounds& bounds, const glm::mat4& transform) {
  Bounds out;
  if (!bounds.valid()) return out;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 corner(i & 1 ? bounds.max.x : bounds.min.x, i & 2 ? bounds.max.y : bounds.min.y,
                           i & 4 ? bounds.max.z : bounds.min.z);
    out.expand(glm::vec3(transform * glm::vec4(corner, 1.0f)));
  }
  return out;
}

Bounds Scene::meshBounds(uint32_t mesh) const {
  Bounds bounds;
  for (const Primitive& primitive : meshes[mesh].primitives) {
    for (uint32_t i = 0; i < primitive.indexCount; ++i)
      bounds.expand(vertices[primitive.vertexOffset + indices[primitive.firstIndex + i]].position);
  }
  return bounds;
}

// Each mesh's bounds once, then eight corners per instance: a scene instancing a mesh 100,000
// times must not walk its triangles 100,000 times.
Bounds Scene::worldBounds() const {
  std::vector<Bounds> local(meshes.size());
  std::vector<bool> known(meshes.size(), false);
  Bounds bounds;
  for (const Instance& instance : instances) {
    if (!known[instance.mesh]) {
      local[instance.mesh] = meshBounds(instance.mesh);
      known[instance.mesh] = true;
    }
    const Bounds placed = transformBounds(local[instance.mesh], instance.transform);
    if (!placed.valid()) continue;
    bounds.expand(placed.min);
    bounds.expand(placed.max);
  }
  return bounds;
}

uint32_t addReversedWindingMesh(Scene& scene, uint32_t mesh) {
  Mesh reversed = scene.meshes[mesh];
  reversed.name += " (reversed winding)";
  for (Primitive& primitive : reversed.primitives) {
    const uint32_t first = uint32_t(scene.indices.size());
    scene.indices.reserve(first + primitive.indexCount);
    for (uint32_t i = 0; i + 2 < primitive.indexCount; i += 3) {
      const uint32_t* triangle = &scene.indices[primitive.firstIndex + i];
      const uint32_t a = triangle[0], b = triangle[1], c = triangle[2];
      scene.indices.insert(scene.indices.end(), {a, c, b});
    }
    primitive.firstIndex = first;
    primitive.indexCount = primitive.indexCount / 3 * 3;
  }
  scene.meshes.push_back(std::move(reversed));
  return uint32_t(scene.meshes.size() - 1);
}

uint64_t Scene::triangleCount() const {
  uint64_t triangles = 0;
  for (const Instance& instance : instances) {
    for (const Primitive& primitive : meshes[instance.mesh].primitives) triangles += primitive.indexCount / 3;
  }
  return triangles;
}

}  // namespace lll
