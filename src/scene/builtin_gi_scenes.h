#pragma once
// Built-in scenes for indirect light (instant radiosity, gi/photons.h), each with a known answer.
#include "scene/scene.h"

namespace lll::builtin {

// A closed Cornell-like room, 5.5 m on a side: red wall at x = 0, green at x = 5.5, white floor,
// ceiling, back and front; one spot light under the ceiling aimed at the red wall's upper half,
// so that no direct light reaches the floor beside it. Behind the green wall a sealed second
// room (x in [5.6, 8]) that no light enters. Cameras: "room" (the default) looks at the back wall
// from just inside the front wall; "sealed" looks down the sealed room.
Scene makeCornell();

// The inside of a closed sphere of radius 3 m, grey (albedo 0.5), double-sided, one white point
// light at its centre: direct irradiance I / R^2 everywhere, and, because every point of a sphere
// sees every other with the same form factor, indirect irradiance after B bounces exactly
// I / R^2 * (rho + ... + rho^B) everywhere (up to the tessellation).
Scene makeSphereRoom();

inline constexpr float kSphereRoomRadius = 3.0f;
inline constexpr float kSphereRoomAlbedo = 0.5f;
inline constexpr float kSphereRoomIntensity = 20.0f;

}  // namespace lll::builtin
