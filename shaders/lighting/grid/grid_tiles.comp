#version 460
#define GRID_BUILD_PASS
// One thread per tile, between and after the grid's count and write passes (specialization
// constant 0): grid-alloc gives the tile's clusters contiguous ranges of the index array (one
// atomic per tile) and sets their write cursors; grid-finish trims a cluster that grid-write filled
// short of its count (never expected; counted in gridCounters.mismatches) and gathers statistics.
#include "common/grid_data.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kFinish = 0u;

void main() {
  uint tile = gl_GlobalInvocationID.x;
  if (tile >= frame.counts.z * frame.counts.w) return;
  uint slices = gridSlices();
  if (kFinish == 0u) {
    uint total = 0u;
    for (uint s = 0u; s < slices; ++s) total += clusters[tile * slices + s].y;
    uint first = total > 0u ? atomicAdd(gridCounters.requested, total) : 0u;
    for (uint s = 0u; s < slices; ++s) {
      uint c = tile * slices + s;
      clusters[c].x = first;
      clusterCursors[c] = first;
      first += clusters[c].y;
    }
    return;
  }
  for (uint s = 0u; s < slices; ++s) {
    uint c = tile * slices + s;
    uvec2 cluster = clusters[c];
    uint written = min(clusterCursors[c], cluster.x + cluster.y) - cluster.x;
    if (clusterCursors[c] != cluster.x + cluster.y) atomicAdd(gridCounters.mismatches, 1u);
    if (written != cluster.y) clusters[c].y = written;
    if (written > 0u) {
      atomicMax(gridCounters.longest, written);
      atomicAdd(gridCounters.clustersWithLights, 1u);
    }
  }
}
