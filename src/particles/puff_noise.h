#pragma once
// The puffs' noise, baked once on the CPU into a small tiling texture (particles/puff.glsl reads it
// with bilinear filtering and wrapping): two octaves of smoothstep-interpolated value noise over
// hashed lattice values, the second at twice the frequency over lattice values of its own, summed
// 0.65 : 0.35, so that a pixel reads both in one texel fetch. Both octaves repeat every
// gpu::kPuffNoisePeriod points of the first octave's lattice.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace lll {

// The hashed value in [0, 1) at lattice point (x, y) of octave `octave` (0 or 1), taken modulo the
// octave's period (kPuffNoisePeriod << octave points).
float puffLatticeValue(int x, int y, int octave);
// One octave's noise at its lattice coordinates `p` (periodic).
float puffValueNoise(glm::vec2 p, int octave);
// What the texture holds at the first octave's lattice coordinates `p`: 0.65 of the first octave at
// p and 0.35 of the second at 2p, in [0, 1).
float puffNoise(glm::vec2 p);
// Side of the texture in texels: period x texels per cell.
uint32_t puffNoiseSide();
// The texture, row by row, as 8-bit UNORM: texel (x, y) holds puffNoise at its centre,
// ((x, y) + 0.5) / texels per cell.
std::vector<uint8_t> bakePuffNoise();

}  // namespace lll
