// The bitonic sort's data: (key, value) pairs of 32-bit words sorted ascending by key, then by
// value, so equal keys still give one order (the sort is a fixed network: no atomics, no subgroup
// operations, the same result on every device).
#ifndef LLL_SORT_PAIRS_GLSL
#define LLL_SORT_PAIRS_GLSL
#include "particles/bitonic.glsl"
#include "shared/particle_types.h"

layout(std430, set = 0, binding = 0) buffer PairBlock {
  uvec2 pairs[];
};
layout(push_constant) uniform SortBlock {
  SortPush sortPush;  // x k, y j, z element count (a power of two)
};

bool pairGreater(uvec2 a, uvec2 b) {
  return a.x > b.x || (a.x == b.x && a.y > b.y);
}

#endif
