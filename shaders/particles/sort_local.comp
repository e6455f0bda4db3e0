#version 460
// The bitonic sort's steps that stay inside one block of 2 x workgroup-size elements, in shared
// memory: kMergeOnly false sorts each block from scratch (k = 2 .. block, alternating direction by
// block so neighbours form bitonic sequences); true finishes merge k for j = block / 2 .. 1.
#include "particles/sort_pairs.glsl"

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const bool kMergeOnly = false;

shared uvec2 block[gl_WorkGroupSize.x * 2u];

void compareExchange(uint k, uint j, uint base) {
  uint i = lowerIndex(gl_LocalInvocationID.x, j);
  uvec2 a = block[i], b = block[i + j];
  if (pairGreater(a, b) == (((base + i) & k) == 0u)) {
    block[i] = b;
    block[i + j] = a;
  }
}

void main() {
  uint size = gl_WorkGroupSize.x * 2u;
  uint base = gl_WorkGroupID.x * size;
  uint t = gl_LocalInvocationID.x;
  block[t] = pairs[base + t];
  block[t + size / 2u] = pairs[base + t + size / 2u];
  barrier();
  if (kMergeOnly) {
    for (uint j = size / 2u; j > 0u; j /= 2u) {
      compareExchange(sortPush.step.x, j, base);
      barrier();
    }
  } else {
    for (uint k = 2u; k <= size; k *= 2u) {
      for (uint j = k / 2u; j > 0u; j /= 2u) {
        compareExchange(k, j, base);
        barrier();
      }
    }
  }
  pairs[base + t] = block[t];
  pairs[base + t + size / 2u] = block[t + size / 2u];
}
