#include "scene/light_animation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <execution>
#include <numbers>

#include "core/errors.h"
#include "scene/hash.h"

namespace lll {

namespace {

constexpr float kTwoPi = 6.28318530718f;

// A value in [0, 1) from (seed, light, stream): a stateless integer hash (the lowbias32
// finaliser), so that a light's motion does not depend on how many lights came before it.
float hash01(uint32_t seed, uint32_t light, uint32_t stream) {
  const uint32_t h = lowbias32(seed * 0x9e3779b9u ^ light * 0x85ebca6bu ^ stream * 0xc2b2ae35u);
  return float(h >> 8) * (1.0f / 16777216.0f);
}

// Where the light is against its orbit's centre. The angles are reduced in double: w t reaches
// 86,400 rad at the largest time, where a float angle would keep only about 8 ms of the period.
// Reduced by 2 pi itself (a float 2 pi is 1.7e-7 rad long, 2.4 mrad after a day's turns; the GPU's
// motion, render/moving_lights.h, counts whole turns exactly).
glm::vec3 offsetAt(const LightMotion& m, float seconds) {
  const double t = seconds, twoPi = 2.0 * std::numbers::pi;
  const float orbit = float(std::fmod(double(m.angularSpeed) * t + m.phase, twoPi));
  const float bob = float(std::fmod(twoPi * m.bobFrequency * t + m.bobPhase, twoPi));
  return {m.radius * std::cos(orbit), m.bobAmplitude * std::sin(bob), m.radius * std::sin(orbit)};
}

}  // namespace

LightAnimation makeLightAnimation(const std::vector<Light>& lights, uint32_t first, uint32_t count,
                                  const Bounds& bounds, uint32_t seed) {
  LightAnimation animation;
  animation.first = first;
  animation.motions.reserve(count);
  const float diagonal = glm::length(bounds.extent());
  for (uint32_t i = 0; i < count; ++i) {
    auto uniform = [&](uint32_t stream, float lo, float hi) {
      return lo + (hi - lo) * hash01(seed, i, stream);
    };
    LightMotion m;
    m.radius = diagonal * uniform(0, 0.01f, 0.04f);
    m.angularSpeed = uniform(1, 0.25f, 1.0f) * (hash01(seed, i, 2) < 0.5f ? -1.0f : 1.0f);
    m.phase = uniform(3, 0.0f, kTwoPi);
    m.bobAmplitude = diagonal * uniform(4, 0.005f, 0.02f);
    m.bobFrequency = uniform(5, 0.1f, 0.4f);
    m.bobPhase = uniform(6, 0.0f, kTwoPi);
    m.origin = lights[first + i].position;
    animation.motions.push_back(m);
  }
  return animation;
}

glm::vec3 orbitCenter(const LightMotion& m) {
  return m.origin - offsetAt(m, 0.0f);
}

glm::vec3 positionAt(const LightMotion& m, float seconds) {
  return m.origin + (offsetAt(m, seconds) - offsetAt(m, 0.0f));
}

void checkAnimationTime(float seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0f || seconds > kMaxAnimationSeconds)
    throw InputError(fmt::format("--time {}: expected seconds from 0 to {}", seconds, kMaxAnimationSeconds));
}

void placeLightsAt(std::vector<Light>& lights, const LightAnimation& animation, float seconds) {
  checkAnimationTime(seconds);
  if (uint64_t(animation.first) + animation.motions.size() > lights.size())
    throw InputError(fmt::format("light animation: {} moving lights from light {}, but the scene has {}",
                                 animation.motions.size(), animation.first, lights.size()));
  // On every core: each light's place is its own (the trigonometry in double of a million lights
  // took 43 ms a frame on one core of a 2-core machine; bench/README.md, "CPU only, 2026-12-05
  // (third)").
  const LightMotion* motions = animation.motions.data();
  Light* moving = lights.data() + animation.first;
  std::for_each(std::execution::par, animation.motions.begin(), animation.motions.end(),
                [&](const LightMotion& m) { moving[&m - motions].position = positionAt(m, seconds); });
}

}  // namespace lll
