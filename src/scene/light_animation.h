#pragma once
// Moving lights: the random lights (--lights) orbit and bob, deterministically for a seed and a
// time, so that "dynamic lights" is something a run can show and a benchmark can measure (every
// technique rebuilds its light data every frame anyway). Each light circles a vertical axis near
// where it was scattered and bobs up and down; at time 0 it is where scatterRandomLights put it.
#include <cstdint>
#include <vector>

#include "scene/scene.h"

namespace lll {

// Times are seconds. Frames of an animated run are this far apart (`lll render --animate`, the
// bench's moving-light scenarios).
inline constexpr float kAnimationFrameSeconds = 1.0f / 60.0f;
// Largest --time: a float keeps the orbits' phases to a few milliradians up to about a day.
inline constexpr float kMaxAnimationSeconds = 86400.0f;

// Motions for `lights[first, first + count)`, seeded: orbit radii 1% to 4% of the scene's
// diagonal, 0.25 to 1 rad/s either way round, bobbing 0.5% to 2% of the diagonal at 0.1 to 0.4 Hz,
// random phases; each centred so that the light is at its current position at time 0. The same
// seed gives the same motions on every machine (they do not use the scattering's random stream).
LightAnimation makeLightAnimation(const std::vector<Light>& lights, uint32_t first, uint32_t count,
                                  const Bounds& bounds, uint32_t seed);

glm::vec3 positionAt(const LightMotion& motion, float seconds);
// The centre of the light's orbit (at the height its bobbing swings about).
glm::vec3 orbitCenter(const LightMotion& motion);

// Throws InputError for a time that is negative, not finite or past kMaxAnimationSeconds.
void checkAnimationTime(float seconds);

// Moves the animated lights to where they are at `seconds` (checked as checkAnimationTime).
void placeLightsAt(std::vector<Light>& lights, const LightAnimation& animation, float seconds);

}  // namespace lll
