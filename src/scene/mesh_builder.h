#pragma once
// Builds triangle meshes in code for the built-in scenes: boxes, quads, surfaces of revolution
// (columns, vases, spheres), round arches, arched wall panels and hanging cloth. Every shape takes
// an object-to-mesh transform, so one builder can assemble a compound piece (a column from base,
// shaft and capital) that the scene then instances many times.
//
// Conventions: front faces are counter-clockwise seen from outside, normals are unit length and
// point out of the solid, curved surfaces get smooth normals and flat ones flat normals. UVs are
// in metres times a per-shape tiling factor, so textures keep their scale across shapes.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace lll {

// A wall panel x in [-width/2, width/2], y in [0, height], z in [-thickness/2, thickness/2],
// pierced by a round-arched opening centred on x = 0: straight jambs from y = 0 up to
// springHeight, then a semicircle of radius archRadius. springHeight 0 gives the spandrel that
// sits on two columns.
struct ArchedWallShape {
  float width = 3.0f;
  float height = 3.0f;
  float thickness = 0.5f;
  float archRadius = 1.0f;
  float springHeight = 0.0f;
  bool closedEnds = true;  // faces at x = +-width/2; leave them off where panels abut
};

// A cloth hanging from its top edge (y = 0, x in [-width/2, width/2]) down to -length. It sags
// between its corners, folds in z with an amplitude that grows towards the hem, and may end in a
// point (`tail` metres longer at the centre than at the sides). Built as two sheets `thickness`
// apart, so it is seen from both sides without double-sided materials. Its UVs span 0..1 across
// and top to bottom (v = 0 at the rod), so a texture shows once on the whole banner.
struct BannerShape {
  float width = 1.0f;
  float length = 3.0f;
  float sag = 0.0f;
  float foldAmplitude = 0.05f;
  float folds = 2.0f;  // whole waves across the width
  float tail = 0.0f;
  float thickness = 0.01f;
  uint32_t columns = 16;  // even, so the pointed hem has a vertex at its tip
  uint32_t rows = 32;
};

class MeshBuilder {
 public:
  explicit MeshBuilder(std::string name) : name_(std::move(name)) {}

  // The material of the shapes added after this call. Each material becomes one Primitive.
  void setMaterial(uint32_t material) { material_ = material; }

  // Box of full extents `size` centred on the origin; flat normals.
  void addBox(const glm::mat4& transform, const glm::vec3& size, float uvPerMetre = 1.0f);
  // Axis-aligned box between two corners (convenience over addBox).
  void addBoxBetween(const glm::vec3& lo, const glm::vec3& hi, float uvPerMetre = 1.0f);
  // One quad in the XZ plane, size.x by size.y metres centred on the origin, facing +Y.
  void addQuad(const glm::mat4& transform, const glm::vec2& size, float uvPerMetre = 1.0f);
  // Surface of revolution about +Y of `profile` points (radius, height), listed bottom to top.
  // A point repeated twice makes a crease (flat shading across it). Caps close the ends flat.
  void addLathe(const glm::mat4& transform, std::span<const glm::vec2> profile, uint32_t segments,
                bool capBottom, bool capTop, float uvPerMetre = 1.0f);
  // Cylinder on y in [0, height] with flat caps.
  void addCylinder(const glm::mat4& transform, float radius, float height, uint32_t segments,
                   float uvPerMetre = 1.0f);
  // Sphere centred on the origin.
  void addSphere(const glm::mat4& transform, float radius, uint32_t segments, uint32_t rings);
  // Half ring in the XY plane springing at y = 0 (radii inner..outer, centred on the origin),
  // extruded through z in [-depth/2, depth/2]: an archivolt or a free-standing arch.
  void addArch(const glm::mat4& transform, float innerRadius, float outerRadius, float depth,
               uint32_t segments, float uvPerMetre = 1.0f);
  void addArchedWall(const glm::mat4& transform, const ArchedWallShape& shape, uint32_t segments,
                     float uvPerMetre = 1.0f);
  void addBanner(const glm::mat4& transform, const BannerShape& shape);

  bool empty() const { return parts_.empty(); }

  // Appends the geometry to the scene's vertex and index arrays as a new mesh, one primitive per
  // material, and returns the mesh index. The builder is left empty.
  uint32_t addTo(Scene& scene);

 private:
  struct Part {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
  };

  // Transforms and stores a vertex of the current shape; returns its index in the current part.
  uint32_t vertex(const glm::vec3& position, const glm::vec3& normal, const glm::vec2& uv);
  // Emits a triangle wound so that its face agrees with its vertices' normals (counter-clockwise
  // seen from the side they point to); a transform that mirrors cannot turn faces inside out.
  void triangle(uint32_t a, uint32_t b, uint32_t c);
  void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
  // A flat quad from four corners in order around it, all with normal `normal`.
  void flatQuad(const glm::vec3 corners[4], const glm::vec3& normal, const glm::vec2 uvs[4]);
  void beginShape(const glm::mat4& transform);
  void addArchedWallFaces(const ArchedWallShape& shape, std::span<const float> angles, float z,
                          float uvPerMetre);
  void addBannerSheet(const BannerShape& shape, float side);

  std::string name_;
  uint32_t material_ = 0;
  std::map<uint32_t, Part> parts_;
  Part* part_ = nullptr;
  glm::mat4 transform_{1.0f};
  glm::mat3 normalMatrix_{1.0f};
};

// Adds an instance of `mesh` and returns its index.
uint32_t addInstance(Scene& scene, uint32_t mesh, const glm::mat4& transform = glm::mat4(1.0f));

}  // namespace lll
