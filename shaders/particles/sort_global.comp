#version 460
// One step (k, j) of the bitonic sort over the whole array, for compare distances too large for a
// workgroup's shared block: each thread orders one pair, ascending where bit k of its index is 0.
#include "particles/sort_pairs.glsl"

layout(local_size_x_id = 0) in;

void main() {
  uint t = gl_GlobalInvocationID.x;
  if (t >= sortPush.step.z / 2u) return;
  uint k = sortPush.step.x, j = sortPush.step.y;
  uint i = lowerIndex(t, j);
  uvec2 a = pairs[i], b = pairs[i + j];
  if (pairGreater(a, b) == ((i & k) == 0u)) {
    pairs[i] = b;
    pairs[i + j] = a;
  }
}
