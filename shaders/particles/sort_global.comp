#version 460
// kSteps consecutive steps (k, j), (k, j / 2) .. (k, j >> (kSteps - 1)) of the bitonic sort over
// the whole array, for compare distances too large for a workgroup's shared block: each invocation
// holds the 2^kSteps elements those steps compare among themselves (spaced by the smallest
// distance) in registers, so one dispatch and one pass over memory does what took kSteps. The
// order is the network's, ascending where bit k of the index is 0 (the same for all of them: k is
// above every bit the steps touch).
#include "particles/sort_pairs.glsl"

layout(local_size_x_id = 0) in;
layout(constant_id = 1) const uint kSteps = 1u;
const uint kElements = 1u << kSteps;

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= sortPush.step.z >> kSteps) return;
  uint k = sortPush.step.x, j = sortPush.step.y;
  uint spacing = j >> (kSteps - 1u);
  uint low = t & (spacing - 1u);
  uint first = ((t - low) << kSteps) + low;  // t with kSteps zero bits put in at bit log2(spacing)
  uvec2 v[kElements];
  for (uint q = 0u; q < kElements; ++q) v[q] = pairs[first + q * spacing];
  bool ascending = (first & k) == 0u;
  for (uint d = kElements / 2u; d > 0u; d /= 2u)
    for (uint q = 0u; q < kElements; ++q)
      if ((q & d) == 0u) {
        uvec2 a = v[q], b = v[q + d];
        if (pairGreater(a, b) == ascending) {
          v[q] = b;
          v[q + d] = a;
        }
      }
  for (uint q = 0u; q < kElements; ++q) pairs[first + q * spacing] = v[q];
}
