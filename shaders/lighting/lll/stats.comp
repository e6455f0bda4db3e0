#version 460
#define LLL_WRITES_COUNTERS
// Longest and total list length, for --stats (run on captured frames only).
#include "common/frame.glsl"
#include "common/lll_walk.glsl"

layout(local_size_x = 64) in;

void main() {
  uint tile = gl_GlobalInvocationID.x;
  if (tile >= frame.counts.z * frame.counts.w) return;
  uint length = listLength(tile);
  if (length == 0u) return;
  atomicMax(counters.longestList, length);
  atomicAdd(counters.totalListLength, length);
  atomicAdd(counters.tilesWithLights, 1u);
}
