#pragma once
// Particle presets: JSON files that describe an emitter and how its particles move and look.
// The built-in ones (particles/presets/*.json: smoke, sparks, dust) are embedded in the binary;
// any other .json path is read from disk. Every field is required and checked: a missing,
// ill-typed or out-of-range field is an InputError naming the file and the field.
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace lll {

enum class EmitterShape { Point, Disc, Sphere };
enum class FloorMode { None, Bounce, Kill };

struct ParticlePreset {
  std::string source;  // built-in name or file path, for messages
  uint32_t count = 0;  // slots: the most particles alive at once; the emitter spawns
                       // count / lifetimeMax per second so a slot is free when it is reused
  float lifetimeMin = 1.0f, lifetimeMax = 1.0f;  // seconds
  EmitterShape shape = EmitterShape::Point;
  float emitterRadius = 0.0f;              // disc (horizontal) or sphere radius, m
  glm::vec3 emitterOffset{0.0f};           // from the scene's smoke source (or --particle-emitter)
  glm::vec3 direction{0.0f, 1.0f, 0.0f};   // launch direction (unit)
  float spreadDegrees = 0.0f;              // half-angle of the launch cone
  float speedMin = 0.0f, speedMax = 0.0f;  // m/s
  glm::vec3 gravity{0.0f};                 // m/s^2
  float buoyancy = 0.0f;                   // upward m/s^2 at birth, fading to 0 at death (cooling)
  float drag = 0.0f;                       // 1/s: velocity decays as exp(-drag t)
  float turbulenceStrength = 0.0f;         // m/s^2 of curl-noise acceleration
  float turbulenceSize = 1.0f;             // m: feature size of the noise field
  float turbulenceSpeed = 0.0f;            // 1/s: how fast the field drifts
  float spin = 0.0f;                       // max rad/s of a particle's rotation
  FloorMode floor = FloorMode::None;       // the plane through the source point (offset not added)
  float restitution = 0.0f;                // bounce: share of the vertical speed kept
  std::vector<float> size;                 // radius over life, m (1..8 evenly spaced keys)
  float sizeVariation = 0.0f;              // each particle's size scaled by 1 +- this
  std::vector<glm::vec3> color;            // albedo over life (linear rgb)
  float colorVariation = 0.0f;             // each particle's brightness scaled by 1 +- this
  std::vector<float> opacity;              // over life
  std::vector<float> emission;             // emitted radiance over life, a multiple of the colour
  float wrap = 0.0f;                       // wrapped diffuse: light reaches this far past the terminator
  float back = 0.0f;                       // back lighting: light behind the particle shining through
  float focus = 1.0f;                      // exponent narrowing the back-lit cone
  float softness = 0.1f;                   // m over which a particle fades out where it meets geometry
  float additive = 0.0f;                   // 0: alpha blending, 1: additive (sparks)
};

// The built-in preset names, sorted.
std::vector<std::string> builtinParticlePresets();

// A built-in name, or a path to a .json file. Throws InputError naming the preset and the field.
ParticlePreset loadParticlePreset(const std::string& nameOrPath);

// Parses and checks preset JSON text; `source` names it in messages.
ParticlePreset parseParticlePreset(const std::string& text, const std::string& source);

// The preset as JSON text that parseParticlePreset reads back to the same preset (the viewer's
// preset editor saves with it; `description` goes into the file's description field).
std::string particlePresetJson(const ParticlePreset& preset, const std::string& description);

// Steps (1 / kParticleStepsPerSecond each) after which the emitter has filled its slots (every slot has
// been spawned once and the oldest particles have started dying): the plume's steady state.
uint32_t stepsToSteadyState(const ParticlePreset& preset);

}  // namespace lll
