#pragma once
// The puffs' noise: smoothstep-interpolated value noise over hashed lattice values, the lattice
// repeating every gpu::kPuffNoisePeriod points. The values are made once on the CPU into a small
// texture, a texel per lattice point, which particles/puff.glsl interpolates (the compute
// renderer from a copy in shared memory).
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lll {

// The hashed value in [0, 1) at lattice point (x, y), taken modulo the period.
float puffLatticeValue(int x, int y);
// The noise at lattice coordinates `p` (periodic).
float puffValueNoise(glm::vec2 p);
// Side of the texture in texels: the period.
uint32_t puffNoiseSide();
// The texture, row by row, as 8-bit UNORM: texel (x, y) holds lattice point (x, y)'s value.
std::vector<uint8_t> bakePuffNoise();
// The noise at `p` as the shaders compute it from `texels` (bakePuffNoise's): the smoothstep
// interpolation of the four 8-bit lattice values about it.
float puffNoiseFromTexels(const std::vector<uint8_t>& texels, glm::vec2 p);

}  // namespace lll
