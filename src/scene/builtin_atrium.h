#pragma once
// The atrium built in code (see builtin_scenes.h): its layout, shared by the geometry and the
// lights, and the pieces builtin_scenes.cpp assembles into the "atrium" and "threel*" scenes.
#include <array>
#include <cmath>
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace lll::builtin {

// The courtyard is centred on the origin, long side along x. Around it run two storeys of
// arcades on a square grid of column lines, then an aisle and the outer walls.
namespace atrium {
inline constexpr float kCourtHalfX = 15.0f;  // column lines at x = +-15 ...
inline constexpr float kCourtHalfZ = 7.0f;   // ... and z = +-7: a 30 m x 14 m courtyard
inline constexpr float kAisleWidth = 4.0f;   // column line to the outer wall's inner face
inline constexpr float kOuterWallThickness = 0.5f;
inline constexpr int kLongBays = 8;   // 3.75 m bays along x
inline constexpr int kShortBays = 4;  // 3.5 m bays along z
inline constexpr float kArcadeThickness = 0.7f;
inline constexpr float kGroundSpring = 4.0f;  // top of the ground-floor columns
inline constexpr float kGalleryFloor = 6.5f;  // the upper storey's floor
inline constexpr float kSlabThickness = 0.3f;
inline constexpr float kUpperSpring = 9.7f;
inline constexpr float kRoofBottom = 12.0f;
inline constexpr float kRoofTop = 12.3f;
}  // namespace atrium

// One side of the courtyard: its first column, the direction along it, and the rotation about +Y
// that turns a piece built facing +z so that it faces the courtyard.
struct ArcadeRow {
  glm::vec3 start;
  glm::vec3 along;
  float rotation;
  int bays;
  float bayWidth;

  glm::vec3 towardsCourtyard() const { return glm::vec3(std::sin(rotation), 0.0f, std::cos(rotation)); }
  glm::vec3 bayCentre(int bay) const { return start + along * (bayWidth * (float(bay) + 0.5f)); }
  glm::vec3 column(int k) const { return start + along * (bayWidth * float(k)); }
  // Places a piece built facing +z, centred on x = 0, at `position` (height included).
  glm::mat4 placement(const glm::vec3& position) const;
};

// The four rows, each owning the column at its start (24 columns in all).
std::array<ArcadeRow, 4> arcadeRows();

// The atrium's textures, materials, geometry and cameras; no lights, no smoke source.
Scene makeAtriumGeometry();

// The default scene's lights: ~100 coloured point lights in the arcades, along the gallery, near
// the floor and hovering in the courtyard, and spot lights from the upper gallery.
void addAtriumLights(Scene& scene);

// The air over the courtyard, clear of its arcades and objects: where benchmark lights float.
Bounds atriumCourtyardVolume();

}  // namespace lll::builtin
