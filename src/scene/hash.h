#pragma once
// Stateless integer hashing for procedural content made on the CPU (built-in textures, moving
// lights): the same inputs give the same values on every machine, with no random stream to share.
#include <cstdint>

namespace lll {

// The "lowbias32" finaliser (two multiply-xorshift rounds): mixes every input bit into every output
// bit; callers combine their inputs into `h` first.
inline uint32_t lowbias32(uint32_t h) {
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h;
}

}  // namespace lll
