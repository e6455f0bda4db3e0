#pragma once
// Coarse meshes that bound a light's exact volume, for techniques that draw lights as geometry
// (the light linked list's raster fills, deferred light volumes, stencil volumes).
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace lll {

struct VolumeMesh {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

// An icosphere (one subdivision: 42 vertices, 80 triangles) scaled so every face lies outside the
// unit sphere: scaling it by r contains the sphere of radius r.
VolumeMesh sphereShell();

// A cone with `sides` flat sides: apex at the origin, axis +Z, length 1, its base ring polygon at
// z = 1 circumscribing the circle of radius 1, and a flat cap. Scaling x and y by len * tan(angle)
// and z by len contains the cone of that half-angle truncated at axial length len, and so the
// spot light volume (cone intersected with the range sphere) when len = range.
VolumeMesh coneShell(uint32_t sides = 16);

// The cube [-1, 1]^3 (8 vertices, 12 triangles): mapped onto a box light's axes it is the exact
// box, so a box light's shell adds nothing beyond its volume.
VolumeMesh boxShell();

}  // namespace lll
