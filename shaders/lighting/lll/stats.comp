#version 460
#define LLL_WRITES_COUNTERS
// Longest and total list length over every list (a tile's, or each of its depth slices' with
// --lll-slices; each class's with --vpl-interleave), for --stats (run on captured frames only).
#include "common/frame.glsl"
#include "common/lll_walk.glsl"

layout(local_size_x = 64) in;

void main() {
  uint list = gl_GlobalInvocationID.x;
  if (list >= frame.counts.z * frame.counts.w * listSlices() * listClasses()) return;
  uint length = listLength(list);
  if (length == 0u) return;
  atomicMax(counters.longestList, length);
  atomicAdd(counters.totalListLength, length);
  atomicAdd(counters.listsWithLights, 1u);
}
