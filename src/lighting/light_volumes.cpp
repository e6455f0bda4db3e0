#include "lighting/light_volumes.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lll {

namespace {

uint32_t midpoint(VolumeMesh& mesh, std::map<std::pair<uint32_t, uint32_t>, uint32_t>& cache, uint32_t a,
                  uint32_t b) {
  const auto key = std::minmax(a, b);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
  return cache[key] = uint32_t(mesh.positions.size() - 1);
}

}  // namespace

VolumeMesh sphereShell() {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  VolumeMesh mesh;
  for (glm::vec3 p : {glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0),
                      glm::vec3(0, -1, t), glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t),
                      glm::vec3(t, 0, -1), glm::vec3(t, 0, 1), glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)})
    mesh.positions.push_back(glm::normalize(p));
  const std::vector<uint32_t> faces = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                       4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                       6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> cache;
  for (size_t f = 0; f < faces.size(); f += 3) {
    const uint32_t a = faces[f], b = faces[f + 1], c = faces[f + 2];
    const uint32_t ab = midpoint(mesh, cache, a, b), bc = midpoint(mesh, cache, b, c),
                   ca = midpoint(mesh, cache, c, a);
    mesh.indices.insert(mesh.indices.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
  }
  // Push every face plane out to distance >= 1 from the centre.
  float nearest = 1.0f;
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                    c = mesh.positions[mesh.indices[i + 2]];
    nearest = std::min(nearest, std::abs(glm::dot(glm::normalize(glm::cross(b - a, c - a)), a)));
  }
  for (glm::vec3& p : mesh.positions) p /= nearest;
  return mesh;
}

VolumeMesh coneShell(uint32_t sides) {
  VolumeMesh mesh;
  const float pi = 3.14159265358979f;
  const float ring = 1.0f / std::cos(pi / float(sides));  // polygon circumscribing the unit circle
  mesh.positions.push_back(glm::vec3(0.0f));              // apex
  mesh.positions.push_back(glm::vec3(0.0f, 0.0f, 1.0f));  // cap centre
  for (uint32_t i = 0; i < sides; ++i) {
    const float a = 2.0f * pi * float(i) / float(sides);
    mesh.positions.push_back(glm::vec3(ring * std::cos(a), ring * std::sin(a), 1.0f));
  }
  for (uint32_t i = 0; i < sides; ++i) {
    const uint32_t p = 2 + i, q = 2 + (i + 1) % sides;
    mesh.indices.insert(mesh.indices.end(), {0, q, p, 1, p, q});
  }
  return mesh;
}

VolumeMesh boxShell() {
  VolumeMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.positions.push_back(glm::vec3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f));
  // Two triangles per face, counter-clockwise seen from outside.
  mesh.indices = {0, 2, 3, 0, 3, 1,   // -z
                  4, 5, 7, 4, 7, 6,   // +z
                  0, 1, 5, 0, 5, 4,   // -y
                  2, 6, 7, 2, 7, 3,   // +y
                  0, 4, 6, 0, 6, 2,   // -x
                  1, 3, 7, 1, 7, 5};  // +x
  return mesh;
}

}  // namespace lll
