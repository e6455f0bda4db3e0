#pragma once
// The puffs' noise, baked once on the CPU into a small tiling texture (particles/puff.glsl reads it
// with bilinear filtering and wrapping): two octaves of smoothstep-interpolated value noise over
// hashed lattice values, the lattice repeating every gpu::kPuffNoisePeriod points.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lll {

// The hashed value in [0, 1) at lattice point (x, y), taken modulo the period.
float puffLatticeValue(int x, int y);
// The noise at lattice coordinates `p` (periodic).
float puffValueNoise(glm::vec2 p);
// The puffs' noise at `p`: 0.65 of the value noise at p and 0.35 of it at twice the frequency, on
// lattice values of its own (an offset lattice), so overlapping puffs do not read as discs. Periodic
// with the lattice's period, so one tiling texture holds both octaves.
float puffNoise(glm::vec2 p);
// Side of the texture in texels: period x texels per cell.
uint32_t puffNoiseSide();
// The texture, row by row, as 8-bit UNORM: texel (x, y) holds puffNoise at its centre,
// ((x, y) + 0.5) / texels per cell.
std::vector<uint8_t> bakePuffNoise();

}  // namespace lll
