#pragma once
// What the photon tracer and the path-traced reference share: directions about an axis, and
// deterministic parallel loops (each index writes only its own output, so the result does not
// depend on which thread took it).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <mutex>
#include <thread>
#include <vector>

#include "gi/random.h"

namespace lll::gi {

inline constexpr float kPi = 3.14159265358979f;

// Two unit vectors completing `axis` (unit) to an orthonormal frame.
inline void perpendiculars(const glm::vec3& axis, glm::vec3& t, glm::vec3& b) {
  const glm::vec3 helper = std::abs(axis.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t = glm::normalize(glm::cross(helper, axis));
  b = glm::cross(axis, t);
}

// A unit vector about `axis` at polar cosine `cosTheta` and azimuth `phi`.
inline glm::vec3 aroundAxis(const glm::vec3& axis, float cosTheta, float phi) {
  glm::vec3 t, b;
  perpendiculars(axis, t, b);
  const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return glm::normalize(t * (sinTheta * std::cos(phi)) + b * (sinTheta * std::sin(phi)) + axis * cosTheta);
}

// A unit vector about `axis` with cosine-distributed polar angle (pdf cos / pi): a diffuse bounce.
inline glm::vec3 cosineAbout(const glm::vec3& axis, Random& random) {
  const float u = random.uniform();
  return aroundAxis(axis, std::sqrt(1.0f - u), 2.0f * kPi * random.uniform());
}

// Calls work(i) for every i in [0, count) on `threads` threads (0: one per hardware thread), the
// indices taken in order; then progress(fraction of indices done), one call at a time.
template <typename Work>
void parallelFor(uint32_t count, uint32_t threads, Work&& work, const std::function<void(double)>& progress) {
  const uint32_t used =
      std::min(std::max(1u, threads ? threads : std::thread::hardware_concurrency()), std::max(count, 1u));
  std::atomic<uint32_t> next{0};
  uint32_t done = 0;
  std::mutex progressMutex;
  auto run = [&] {
    for (uint32_t i; (i = next.fetch_add(1)) < count;) {
      work(i);
      if (progress) {
        const std::lock_guard lock(progressMutex);
        progress(double(++done) / count);
      }
    }
  };
  std::vector<std::thread> pool;
  for (uint32_t t = 1; t < used; ++t) pool.emplace_back(run);
  run();
  for (std::thread& t : pool) t.join();
}

}  // namespace lll::gi
