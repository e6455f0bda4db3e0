#version 460
#define LLL_BINS_WRITE
// The bins' count and scatter passes (specialization constant 0: 0 counts, 1 scatters): one thread
// per light visits the cells its bounding sphere covers on screen and, where the light reaches the
// depth of the cell's farthest surface, counts itself there or appends itself at the cell's cursor.
// Both passes visit the same cells, so the scatter fills exactly the counted ranges.
#include "common/light_bins.glsl"
#include "common/light_tile_test.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kScatter = 0u;

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= binHeader.lightCount) return;
  vec4 positionRange = lights[index].positionRange;  // w bounds every light type (boxes too)
  vec3 center = toViewDepthSpace(positionRange.xyz);
  float radius = positionRange.w;
  uvec4 cells;
  if (!sphereCells(center, radius, cells)) return;
  float nearest = center.z - radius;
  for (uint y = cells.y; y <= cells.w; ++y) {
    for (uint x = cells.x; x <= cells.z; ++x) {
      uint cell = y * binHeader.cellsX + x;
      if (nearest > uintBitsToFloat(binCells[cell].farBits)) continue;  // behind every surface
      if (kScatter == 0u) {
        atomicAdd(binCells[cell].count, 1u);
      } else {
        uint slot = atomicAdd(binCells[cell].cursor, 1u);
        if (slot < binHeader.capacity) binLights[slot] = index;
      }
    }
  }
}
