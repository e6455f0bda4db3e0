#version 460
// The bitonic sort's steps that stay inside one block of kBlock elements, in shared memory (each
// invocation orders kBlock / 2 / workgroup-size pairs a step): kMergeOnly false sorts each block
// from scratch (k = 2 .. block, alternating direction by block so neighbours form bitonic
// sequences); true finishes merge k for j = block / 2 .. 1.
#include "particles/sort_pairs.glsl"

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const bool kMergeOnly = false;
layout(constant_id = 2) const uint kBlock = 1024u;

shared uvec2 block[kBlock];

void compareExchange(uint k, uint j, uint base) {
  for (uint p = gl_LocalInvocationID.x; p < kBlock / 2u; p += gl_WorkGroupSize.x) {
    uint i = lowerIndex(p, j);
    uvec2 a = block[i], b = block[i + j];
    if (pairGreater(a, b) == (((base + i) & k) == 0u)) {
      block[i] = b;
      block[i + j] = a;
    }
  }
}

void main() {
  uint base = gl_WorkGroupID.x * kBlock;
  for (uint e = gl_LocalInvocationID.x; e < kBlock; e += gl_WorkGroupSize.x) block[e] = pairs[base + e];
  barrier();
  if (kMergeOnly) {
    for (uint j = kBlock / 2u; j > 0u; j /= 2u) {
      compareExchange(sortPush.step.x, j, base);
      barrier();
    }
  } else {
    for (uint k = 2u; k <= kBlock; k *= 2u) {
      for (uint j = k / 2u; j > 0u; j /= 2u) {
        compareExchange(k, j, base);
        barrier();
      }
    }
  }
  for (uint e = gl_LocalInvocationID.x; e < kBlock; e += gl_WorkGroupSize.x) pairs[base + e] = block[e];
}
