#pragma once
// The CPU ray work's random numbers: PCG32 (O'Neill 2014), one stream per photon or pixel sample,
// seeded from (seed, index). Written here rather than taken from <random> because the standard's
// distributions differ between library implementations, and a seed must give the same VPLs and
// the same reference image on every machine and for any thread count.
#include <cstdint>

namespace lll::gi {

class Random {
 public:
  Random(uint64_t seed, uint64_t stream) {
    state_ = 0;
    increment_ = (splitMix(stream ^ 0x9E3779B97F4A7C15ull) << 1u) | 1u;
    next();
    state_ += splitMix(seed);
    next();
  }

  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + increment_;
    const uint32_t shifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rotation = uint32_t(old >> 59u);
    return (shifted >> rotation) | (shifted << ((32u - rotation) & 31u));
  }

  // Uniform in [0, 1): the top 24 bits, so that 1 itself never comes out of the rounding.
  float uniform() { return float(next() >> 8) * (1.0f / 16777216.0f); }

 private:
  static uint64_t splitMix(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
  }

  uint64_t state_;
  uint64_t increment_;
};

}  // namespace lll::gi
