// The puffs' noise (particles/puff_noise.h): the texture holds the lattice's values, the noise
// repeats without a seam, and the shaders' interpolation of the texels is the smooth value noise up
// to the texels' rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "particles/puff_noise.h"
#include "shared/particle_types.h"

namespace lll {
namespace {

TEST(PuffNoise, TexelsHoldTheLatticeValues) {
  const std::vector<uint8_t> texels = bakePuffNoise();
  const uint32_t side = puffNoiseSide();
  ASSERT_EQ(side, gpu::kPuffNoisePeriod);
  ASSERT_EQ(texels.size(), size_t(side) * side);
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x)
      EXPECT_NEAR(texels[size_t(y) * side + x] / 255.0f, puffLatticeValue(int(x), int(y)),
                  0.5f / 255.0f + 1e-6f);
}

TEST(PuffNoise, RepeatsWithItsPeriodAndWithoutASeam) {
  const float period = float(gpu::kPuffNoisePeriod);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-100.0f, 100.0f);
  for (int i = 0; i < 200; ++i) {
    const glm::vec2 p(coordinate(rng), coordinate(rng));
    EXPECT_NEAR(puffValueNoise(p), puffValueNoise(p + glm::vec2(period, 0.0f)), 1e-4f);
    EXPECT_NEAR(puffValueNoise(p), puffValueNoise(p - glm::vec2(0.0f, period)), 1e-4f);
  }
  // Across the texture's wrap the step between neighbours is no larger than inside it.
  const std::vector<uint8_t> texels = bakePuffNoise();
  const int side = int(puffNoiseSide());
  int inside = 0, seam = 0;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x + 1 < side; ++x)
      inside = std::max(inside, std::abs(texels[y * side + x + 1] - texels[y * side + x]));
    seam = std::max(seam, std::abs(texels[y * side] - texels[y * side + side - 1]));
  }
  EXPECT_LE(seam, inside);
}

// The shaders' noise (the smoothstep interpolation of the 8-bit lattice values, particles/puff.glsl)
// against the smooth noise of unrounded values: the rounding only, half a step of 255.
TEST(PuffNoise, InterpolatedTexelsStayCloseToTheSmoothNoise) {
  const std::vector<uint8_t> texels = bakePuffNoise();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> coordinate(-70.0f, 150.0f);
  float worst = 0.0f, mean = 0.0f;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const glm::vec2 p(coordinate(rng), coordinate(rng));
    const float exact = puffValueNoise(p);
    worst = std::max(worst, std::abs(puffNoiseFromTexels(texels, p) - exact));
    mean += exact;
  }
  EXPECT_LE(worst, 0.5f / 255.0f + 1e-6f);
  EXPECT_NEAR(mean / n, 0.5f, 0.03f) << "lattice values spread over [0, 1)";
  // At the lattice points the noise is the texel.
  for (int y = -3; y < 70; y += 7)
    for (int x = -5; x < 70; x += 5) {
      const int mask = int(gpu::kPuffNoisePeriod) - 1;
      EXPECT_EQ(puffNoiseFromTexels(texels, glm::vec2(x, y)),
                float(texels[size_t(y & mask) * gpu::kPuffNoisePeriod + size_t(x & mask)]) / 255.0f);
    }
  std::printf("[ noise    ] shaders' against exact: worst %.4f\n", worst);
}

}  // namespace
}  // namespace lll
