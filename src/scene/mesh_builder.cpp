#include "scene/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

namespace lll {

namespace {

constexpr float kPi = glm::pi<float>();

// Where the ray from the arch centre at `angle` leaves the spandrel rectangle
// [-halfWidth, halfWidth] x [0, rise] (coordinates relative to the arch centre).
glm::vec2 spandrelBoundary(float angle, float halfWidth, float rise) {
  const glm::vec2 dir(std::cos(angle), std::sin(angle));
  float t = std::numeric_limits<float>::max();
  if (std::abs(dir.x) > 1e-6f) t = halfWidth / std::abs(dir.x);
  if (dir.y > 1e-6f) t = std::min(t, rise / dir.y);
  return t * dir;
}

// Arch angles from 0 to pi, with the spandrel's two upper corners added so that every quad
// between the arch and the rectangle has its outer edge on a single side of the rectangle.
std::vector<float> archAngles(uint32_t segments, float halfWidth, float rise) {
  std::vector<float> angles;
  for (uint32_t i = 0; i <= segments; ++i) angles.push_back(kPi * float(i) / float(segments));
  const float corner = std::atan2(rise, halfWidth);
  for (float extra : {corner, kPi - corner}) {
    const bool present =
        std::any_of(angles.begin(), angles.end(), [&](float a) { return std::abs(a - extra) < 1e-4f; });
    if (!present) angles.push_back(extra);
  }
  std::sort(angles.begin(), angles.end());
  return angles;
}

// The unit outward normal of a lathe profile at point i, from its neighbours within the same
// smooth run (a repeated point ends a run). On the axis the surface closes, so it is vertical.
glm::vec2 profileNormal(std::span<const glm::vec2> profile, size_t i) {
  const size_t prev = (i > 0 && profile[i - 1] != profile[i]) ? i - 1 : i;
  const size_t next = (i + 1 < profile.size() && profile[i + 1] != profile[i]) ? i + 1 : i;
  const glm::vec2 tangent = profile[next] - profile[prev];
  glm::vec2 normal = glm::normalize(glm::vec2(tangent.y, -tangent.x));
  if (profile[i].x <= 0.0f) normal = glm::vec2(0.0f, normal.y >= 0.0f ? 1.0f : -1.0f);
  return normal;
}

}  // namespace

void MeshBuilder::beginShape(const glm::mat4& transform) {
  part_ = &parts_[material_];
  transform_ = transform;
  normalMatrix_ = glm::transpose(glm::inverse(glm::mat3(transform)));
}

uint32_t MeshBuilder::vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv) {
  Vertex v;
  v.position = glm::vec3(transform_ * glm::vec4(position, 1.0f));
  v.normal = glm::normalize(normalMatrix_ * normal);
  v.uv = uv;
  part_->vertices.push_back(v);
  return uint32_t(part_->vertices.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) {
  const std::vector<Vertex>& v = part_->vertices;
  const glm::vec3 face = glm::cross(v[b].position - v[a].position, v[c].position - v[a].position);
  // Collapsed triangles (at a lathe's pole, a pointed hem) draw nothing.
  if (glm::dot(face, face) < 1e-18f) return;
  const glm::vec3 normalSum = v[a].normal + v[b].normal + v[c].normal;
  if (glm::dot(face, normalSum) < 0.0f) std::swap(b, c);
  part_->indices.insert(part_->indices.end(), {a, b, c});
}

void MeshBuilder::quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  triangle(a, b, c);
  triangle(a, c, d);
}

void MeshBuilder::flatQuad(const glm::vec3 corners[4], const glm::vec3& normal, const glm::vec2 uvs[4]) {
  uint32_t ids[4];
  for (int i = 0; i < 4; ++i) ids[i] = vertex(corners[i], normal, uvs[i]);
  quad(ids[0], ids[1], ids[2], ids[3]);
}

void MeshBuilder::addBox(const glm::mat4& transform, const glm::vec3& size, float uvPerMetre) {
  beginShape(transform);
  const glm::vec3 half = 0.5f * size;
  // Each face: its normal and two in-plane axes with u x v = normal.
  struct Face {
    glm::vec3 n, u, v;
  };
  static const Face faces[6] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
  };
  static const glm::vec2 signs[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (const Face& f : faces) {
    glm::vec3 corners[4];
    glm::vec2 uvs[4];
    for (int i = 0; i < 4; ++i) {
      corners[i] = half * (f.n + signs[i].x * f.u + signs[i].y * f.v);
      uvs[i] = uvPerMetre * glm::vec2(glm::dot(corners[i], f.u), glm::dot(corners[i], f.v));
    }
    flatQuad(corners, f.n, uvs);
  }
}

void MeshBuilder::addBoxBetween(const glm::vec3& lo, const glm::vec3& hi, float uvPerMetre) {
  addBox(glm::translate(glm::mat4(1.0f), 0.5f * (lo + hi)), hi - lo, uvPerMetre);
}

void MeshBuilder::addQuad(const glm::mat4& transform, const glm::vec2& size, float uvPerMetre) {
  beginShape(transform);
  const glm::vec2 half = 0.5f * size;
  const glm::vec3 corners[4] = {
      {-half.x, 0, half.y}, {half.x, 0, half.y}, {half.x, 0, -half.y}, {-half.x, 0, -half.y}};
  glm::vec2 uvs[4];
  for (int i = 0; i < 4; ++i) uvs[i] = uvPerMetre * glm::vec2(corners[i].x, -corners[i].z);
  flatQuad(corners, glm::vec3(0, 1, 0), uvs);
}

void MeshBuilder::addLathe(const glm::mat4& transform, std::span<const glm::vec2> profile, uint32_t segments,
                           bool capBottom, bool capTop, float uvPerMetre) {
  beginShape(transform);
  const uint32_t ringSize = segments + 1;  // the seam is duplicated so that u runs 0..1
  std::vector<uint32_t> firstOfRing;
  float arcLength = 0.0f;
  for (size_t i = 0; i < profile.size(); ++i) {
    if (i > 0) arcLength += glm::distance(profile[i - 1], profile[i]);
    const glm::vec2 n = profileNormal(profile, i);
    firstOfRing.push_back(uint32_t(part_->vertices.size()));
    for (uint32_t j = 0; j < ringSize; ++j) {
      const float phi = 2.0f * kPi * float(j) / float(segments);
      const glm::vec3 radial(std::sin(phi), 0.0f, std::cos(phi));
      const glm::vec3 position = profile[i].x * radial + glm::vec3(0, profile[i].y, 0);
      vertex(position, n.x * radial + glm::vec3(0, n.y, 0),
             glm::vec2(float(j) / float(segments), arcLength * uvPerMetre));
    }
  }
  for (size_t i = 0; i + 1 < profile.size(); ++i) {
    if (profile[i] == profile[i + 1]) continue;  // a crease: the two rings are not joined
    for (uint32_t j = 0; j < segments; ++j) {
      const uint32_t a = firstOfRing[i] + j, b = firstOfRing[i + 1] + j;
      quad(a, a + 1, b + 1, b);
    }
  }
  auto cap = [&](const glm::vec2& point, float facing) {
    if (point.x <= 0.0f) return;
    const glm::vec3 n(0, facing, 0);
    const uint32_t centre = vertex(glm::vec3(0, point.y, 0), n, glm::vec2(0.0f));
    const uint32_t first = uint32_t(part_->vertices.size());
    for (uint32_t j = 0; j < ringSize; ++j) {
      const float phi = 2.0f * kPi * float(j) / float(segments);
      const glm::vec3 p(point.x * std::sin(phi), point.y, point.x * std::cos(phi));
      vertex(p, n, uvPerMetre * glm::vec2(p.x, p.z));
    }
    for (uint32_t j = 0; j < segments; ++j) triangle(centre, first + j, first + j + 1);
  };
  if (capBottom) cap(profile.front(), -1.0f);
  if (capTop) cap(profile.back(), 1.0f);
}

void MeshBuilder::addCylinder(const glm::mat4& transform, float radius, float height, uint32_t segments,
                              float uvPerMetre) {
  const glm::vec2 profile[2] = {{radius, 0.0f}, {radius, height}};
  addLathe(transform, profile, segments, true, true, uvPerMetre);
}

void MeshBuilder::addSphere(const glm::mat4& transform, float radius, uint32_t segments, uint32_t rings) {
  std::vector<glm::vec2> profile;
  for (uint32_t i = 0; i <= rings; ++i) {
    const float theta = kPi * float(i) / float(rings);
    const bool pole = i == 0 || i == rings;
    profile.emplace_back(pole ? 0.0f : radius * std::sin(theta), -radius * std::cos(theta));
  }
  addLathe(transform, profile, segments, false, false, 1.0f / (kPi * radius));
}

void MeshBuilder::addArch(const glm::mat4& transform, float innerRadius, float outerRadius, float depth,
                          uint32_t segments, float uvPerMetre) {
  beginShape(transform);
  const float zs[2] = {0.5f * depth, -0.5f * depth};
  for (uint32_t i = 0; i < segments; ++i) {
    const float a0 = kPi * float(i) / float(segments), a1 = kPi * float(i + 1) / float(segments);
    const glm::vec3 d0(std::cos(a0), std::sin(a0), 0), d1(std::cos(a1), std::sin(a1), 0);
    for (float z : zs) {  // front and back faces
      const glm::vec3 c[4] = {innerRadius * d0 + glm::vec3(0, 0, z), outerRadius * d0 + glm::vec3(0, 0, z),
                              outerRadius * d1 + glm::vec3(0, 0, z), innerRadius * d1 + glm::vec3(0, 0, z)};
      glm::vec2 uvs[4];
      for (int k = 0; k < 4; ++k) uvs[k] = uvPerMetre * glm::vec2(z > 0 ? c[k].x : -c[k].x, c[k].y);
      flatQuad(c, glm::vec3(0, 0, z > 0 ? 1.0f : -1.0f), uvs);
    }
    for (float radius : {innerRadius, outerRadius}) {  // intrados faces the centre, extrados away
      const float facing = radius == innerRadius ? -1.0f : 1.0f;
      const float u0 = uvPerMetre * radius * a0, u1 = uvPerMetre * radius * a1;
      const float v0 = uvPerMetre * zs[0], v1 = uvPerMetre * zs[1];
      quad(vertex(radius * d0 + glm::vec3(0, 0, zs[0]), facing * d0, {u0, v0}),
           vertex(radius * d1 + glm::vec3(0, 0, zs[0]), facing * d1, {u1, v0}),
           vertex(radius * d1 + glm::vec3(0, 0, zs[1]), facing * d1, {u1, v1}),
           vertex(radius * d0 + glm::vec3(0, 0, zs[1]), facing * d0, {u0, v1}));
    }
  }
  for (float side : {-1.0f, 1.0f}) {  // the two feet
    const glm::vec3 c[4] = {{side * innerRadius, 0, zs[0]},
                            {side * outerRadius, 0, zs[0]},
                            {side * outerRadius, 0, zs[1]},
                            {side * innerRadius, 0, zs[1]}};
    glm::vec2 uvs[4];
    for (int k = 0; k < 4; ++k) uvs[k] = uvPerMetre * glm::vec2(c[k].x, c[k].z);
    flatQuad(c, glm::vec3(0, -1, 0), uvs);
  }
}

void MeshBuilder::addArchedWallFaces(const ArchedWallShape& shape, std::span<const float> angles, float z,
                                     float uvPerMetre) {
  const float halfWidth = 0.5f * shape.width, r = shape.archRadius, spring = shape.springHeight;
  const float facing = z > 0.0f ? 1.0f : -1.0f;
  const glm::vec3 normal(0, 0, facing);
  auto uvOf = [&](const glm::vec3& p) { return uvPerMetre * glm::vec2(facing * p.x, p.y); };
  auto addFace = [&](const glm::vec3(&c)[4]) {
    const glm::vec2 uvs[4] = {uvOf(c[0]), uvOf(c[1]), uvOf(c[2]), uvOf(c[3])};
    flatQuad(c, normal, uvs);
  };
  // Above the spring line the face is a fan of quads from the arch out to the panel's border.
  for (size_t i = 0; i + 1 < angles.size(); ++i) {
    const float a0 = angles[i], a1 = angles[i + 1];
    const glm::vec2 o0 = spandrelBoundary(a0, halfWidth, shape.height - spring);
    const glm::vec2 o1 = spandrelBoundary(a1, halfWidth, shape.height - spring);
    addFace({{r * std::cos(a0), spring + r * std::sin(a0), z},
             {o0.x, spring + o0.y, z},
             {o1.x, spring + o1.y, z},
             {r * std::cos(a1), spring + r * std::sin(a1), z}});
  }
  if (spring <= 0.0f) return;
  for (float side : {-1.0f, 1.0f}) {  // the piers beside the jambs
    addFace(
        {{side * r, 0, z}, {side * halfWidth, 0, z}, {side * halfWidth, spring, z}, {side * r, spring, z}});
  }
}

void MeshBuilder::addArchedWall(const glm::mat4& transform, const ArchedWallShape& shape, uint32_t segments,
                                float uvPerMetre) {
  beginShape(transform);
  const float halfWidth = 0.5f * shape.width, r = shape.archRadius, spring = shape.springHeight;
  const float halfDepth = 0.5f * shape.thickness, top = shape.height;
  const std::vector<float> angles = archAngles(segments, halfWidth, top - spring);
  addArchedWallFaces(shape, angles, halfDepth, uvPerMetre);
  addArchedWallFaces(shape, angles, -halfDepth, uvPerMetre);
  float arcLength = 0.0f;
  for (size_t i = 0; i + 1 < angles.size(); ++i) {  // the intrados, facing the arch's centre
    const glm::vec3 d0(std::cos(angles[i]), std::sin(angles[i]), 0);
    const glm::vec3 d1(std::cos(angles[i + 1]), std::sin(angles[i + 1]), 0);
    const glm::vec3 centre(0, spring, 0);
    const float u0 = uvPerMetre * arcLength;
    arcLength += r * (angles[i + 1] - angles[i]);
    const float u1 = uvPerMetre * arcLength, v0 = uvPerMetre * halfDepth, v1 = -v0;
    quad(vertex(centre + r * d0 + glm::vec3(0, 0, halfDepth), -d0, {u0, v0}),
         vertex(centre + r * d1 + glm::vec3(0, 0, halfDepth), -d1, {u1, v0}),
         vertex(centre + r * d1 - glm::vec3(0, 0, halfDepth), -d1, {u1, v1}),
         vertex(centre + r * d0 - glm::vec3(0, 0, halfDepth), -d0, {u0, v1}));
  }
  // The remaining flat faces: jambs, top, the feet either side of the opening and the two ends.
  auto face = [&](const glm::vec3& lo, const glm::vec3& hi, const glm::vec3& normal) {
    const int axis = normal.x != 0.0f ? 0 : (normal.y != 0.0f ? 1 : 2);
    const int ua = (axis + 1) % 3, va = (axis + 2) % 3;
    glm::vec3 c[4] = {lo, lo, hi, hi};
    c[1][ua] = hi[ua];
    c[3][ua] = lo[ua];
    glm::vec2 uvs[4];
    for (int k = 0; k < 4; ++k) uvs[k] = uvPerMetre * glm::vec2(c[k][ua], c[k][va]);
    flatQuad(c, normal, uvs);
  };
  for (float side : {-1.0f, 1.0f}) {
    if (spring > 0.0f) face({side * r, 0, -halfDepth}, {side * r, spring, halfDepth}, {-side, 0, 0});
    const float inner = side * r, outer = side * halfWidth;
    face({std::min(inner, outer), 0, -halfDepth}, {std::max(inner, outer), 0, halfDepth}, {0, -1, 0});
    if (shape.closedEnds) face({outer, 0, -halfDepth}, {outer, top, halfDepth}, {side, 0, 0});
  }
  face({-halfWidth, top, -halfDepth}, {halfWidth, top, halfDepth}, {0, 1, 0});
}

namespace {

glm::vec3 bannerPoint(const BannerShape& s, float u, float v) {
  const float yTop = -s.sag * 4.0f * u * (1.0f - u);
  const float yHem = -(s.length - s.tail * std::abs(2.0f * u - 1.0f));
  // Folds start as a ripple under the rod and deepen towards the hem, drifting a little sideways.
  const float fold = s.foldAmplitude * std::sin(2.0f * kPi * s.folds * u + 0.9f * v) * (0.3f + 0.7f * v);
  return {(u - 0.5f) * s.width, yTop + (yHem - yTop) * v, fold};
}

}  // namespace

void MeshBuilder::addBannerSheet(const BannerShape& shape, float side) {
  const uint32_t first = uint32_t(part_->vertices.size());
  const float h = 1e-3f;
  for (uint32_t row = 0; row <= shape.rows; ++row) {
    for (uint32_t col = 0; col <= shape.columns; ++col) {
      const float u = float(col) / float(shape.columns), v = float(row) / float(shape.rows);
      const glm::vec3 p = bannerPoint(shape, u, v);
      const glm::vec3 du = bannerPoint(shape, u + h, v) - bannerPoint(shape, u - h, v);
      const glm::vec3 dv = bannerPoint(shape, u, v + h) - bannerPoint(shape, u, v - h);
      const glm::vec3 n = side * glm::normalize(glm::cross(dv, du));  // +z for the front sheet
      vertex(p + 0.5f * shape.thickness * n, n, glm::vec2(u, v));
    }
  }
  const uint32_t stride = shape.columns + 1;
  for (uint32_t row = 0; row < shape.rows; ++row) {
    for (uint32_t col = 0; col < shape.columns; ++col) {
      const uint32_t a = first + row * stride + col;
      quad(a, a + 1, a + 1 + stride, a + stride);
    }
  }
}

void MeshBuilder::addBanner(const glm::mat4& transform, const BannerShape& shape) {
  beginShape(transform);
  addBannerSheet(shape, 1.0f);
  addBannerSheet(shape, -1.0f);
}

uint32_t MeshBuilder::addTo(Scene& scene) {
  Mesh mesh;
  mesh.name = name_;
  for (auto& [material, part] : parts_) {
    if (part.indices.empty()) continue;
    Primitive primitive;
    primitive.firstIndex = uint32_t(scene.indices.size());
    primitive.indexCount = uint32_t(part.indices.size());
    primitive.vertexOffset = uint32_t(scene.vertices.size());
    primitive.material = material;
    mesh.primitives.push_back(primitive);
    scene.vertices.insert(scene.vertices.end(), part.vertices.begin(), part.vertices.end());
    scene.indices.insert(scene.indices.end(), part.indices.begin(), part.indices.end());
  }
  parts_.clear();
  part_ = nullptr;
  scene.meshes.push_back(std::move(mesh));
  return uint32_t(scene.meshes.size() - 1);
}

uint32_t addInstance(Scene& scene, uint32_t mesh, const glm::mat4& transform) {
  scene.instances.push_back(Instance{mesh, transform});
  return uint32_t(scene.instances.size() - 1);
}

}  // namespace lll
