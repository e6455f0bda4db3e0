#include "particles/puff_noise.h"

#include <cmath>

#include "shared/particle_types.h"

namespace lll {

float puffLatticeValue(int x, int y) {
  const int period = int(gpu::kPuffNoisePeriod);
  const uint32_t px = uint32_t(((x % period) + period) % period),
                 py = uint32_t(((y % period) + period) % period);
  // One multiply-xorshift round: the shaders hashed this per pixel before the noise was baked.
  uint32_t h = px * 0x8da6b343u ^ py * 0xd8163841u;
  h = (h ^ (h >> 15u)) * 0x2c1b3c6du;
  h ^= h >> 12u;
  return float(h >> 8u) * (1.0f / 16777216.0f);
}

float puffValueNoise(glm::vec2 p) {
  const glm::vec2 cell = glm::floor(p);
  const glm::vec2 f = p - cell;
  const glm::vec2 u = f * f * (3.0f - 2.0f * f);
  const int x = int(cell.x), y = int(cell.y);
  const float a = puffLatticeValue(x, y), b = puffLatticeValue(x + 1, y);
  const float c = puffLatticeValue(x, y + 1), d = puffLatticeValue(x + 1, y + 1);
  return glm::mix(glm::mix(a, b, u.x), glm::mix(c, d, u.x), u.y);
}

float puffNoise(glm::vec2 p) {
  // The second octave's lattice starts at a point of the first's far from the origin, so its
  // values are not the first octave's at every other lattice point.
  return 0.65f * puffValueNoise(p) + 0.35f * puffValueNoise(2.0f * p + glm::vec2(37.0f, 17.0f));
}

uint32_t puffNoiseSide() {
  return gpu::kPuffNoisePeriod * gpu::kPuffNoiseTexelsPerCell;
}

std::vector<uint8_t> bakePuffNoise() {
  const uint32_t side = puffNoiseSide();
  const float perTexel = 1.0f / float(gpu::kPuffNoiseTexelsPerCell);
  std::vector<uint8_t> texels(size_t(side) * side);
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) {
      const float v = puffNoise((glm::vec2(x, y) + 0.5f) * perTexel);
      texels[size_t(y) * side + x] = uint8_t(std::lround(v * 255.0f));
    }
  return texels;
}

}  // namespace lll
