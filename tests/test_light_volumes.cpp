// The light shells must contain the exact volumes they stand for, or the fills drop lights.
#include <gtest/gtest.h>

#include <cmath>

#include "lighting/light_volumes.h"

namespace lll {
namespace {

// Smallest distance from the origin-side to any face plane, and whether faces wind outward.
void checkFacesOutside(const VolumeMesh& mesh, const glm::vec3& inside, float minDistance) {
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                    c = mesh.positions[mesh.indices[i + 2]];
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    EXPECT_GE(glm::dot(n, a - inside), minDistance - 1e-5f) << "face " << i / 3;
  }
}

TEST(LightVolumes, SphereShellContainsUnitSphere) {
  const VolumeMesh mesh = sphereShell();
  EXPECT_EQ(mesh.positions.size(), 42u);
  EXPECT_EQ(mesh.indices.size(), 240u);
  checkFacesOutside(mesh, glm::vec3(0.0f), 1.0f);
  // Coarse but not wasteful: no vertex farther than 1.3 (ThreeL's shell is 1.07 at its faces).
  for (const glm::vec3& p : mesh.positions) EXPECT_LT(glm::length(p), 1.3f);
}

TEST(LightVolumes, BoxShellIsTheUnitCubeWoundOutwards) {
  const VolumeMesh mesh = boxShell();
  EXPECT_EQ(mesh.positions.size(), 8u);
  EXPECT_EQ(mesh.indices.size(), 36u);
  // Every face at distance exactly 1 from the centre, its normal pointing away from it.
  checkFacesOutside(mesh, glm::vec3(0.0f), 1.0f);
  for (const glm::vec3& p : mesh.positions) EXPECT_FLOAT_EQ(glm::length(p), std::sqrt(3.0f));
}

TEST(LightVolumes, ConeShellContainsTruncatedCone) {
  const VolumeMesh mesh = coneShell(16);
  // Every face lies outside points of the exact cone: sample the cone's boundary circle at z = 1
  // and along its surface; each must be on the inner side of every face plane.
  for (int k = 0; k < 64; ++k) {
    const float a = 2.0f * 3.14159265f * float(k) / 64.0f;
    for (float z : {0.25f, 0.5f, 1.0f}) {
      const glm::vec3 p(z * std::cos(a), z * std::sin(a), z);
      for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 v0 = mesh.positions[mesh.indices[i]], v1 = mesh.positions[mesh.indices[i + 1]],
                        v2 = mesh.positions[mesh.indices[i + 2]];
        const glm::vec3 n = glm::normalize(glm::cross(v1 - v0, v2 - v0));
        EXPECT_LE(glm::dot(n, p - v0), 1e-5f);
      }
    }
  }
}

}  // namespace
}  // namespace lll
