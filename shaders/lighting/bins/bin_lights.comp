#version 460
#define LLL_BINS_WRITE
// The bins' count and scatter passes (specialization constant 0: 0 counts, 1 scatters), and the
// count pass of the large lights (constant 1: 1). A light visits the cells its bounding sphere
// covers on screen and, where it reaches the depth of the cell's farthest surface, counts itself
// there or appends itself at the cell's cursor. Both passes visit the same cells, so the scatter
// fills exactly the counted ranges.
// A light covering at most kSmallLightCells cells is one thread's work. A larger one would leave a
// thread looping over hundreds of cells (a full-screen light at 1080p covers 510), so the count
// pass lists it instead and largeLightGroups() workgroups (light_bins.cpp) visit its cells 64 at a time: in
// the large-light count pass, and in the scatter dispatch's groups past the lights'.
#include "common/light_bins.glsl"
#include "common/light_tile_test.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kScatter = 0u;
layout(constant_id = 1) const uint kLargeOnly = 0u;

const uint kSmallLightCells = 8u;

void binCell(uint index, uint cell) {
  if (kScatter == 0u) {
    atomicAdd(binCells[cell].count, 1u);
  } else {
    uint slot = atomicAdd(binCells[cell].cursor, 1u);
    if (slot < binHeader.capacity) binLights[slot] = index;
  }
}

bool lightCells(uint index, out uvec4 cells, out float nearest) {
  vec4 positionRange = lights[index].positionRange;  // w bounds every light type (boxes too)
  vec3 center = toViewDepthSpace(positionRange.xyz);
  nearest = center.z - positionRange.w;
  return sphereCells(center, positionRange.w, cells);
}

// The large lights, one workgroup at a time from `group` on, each thread one cell in 64.
void binLargeLights(uint group, uint groups) {
  uint largeCount = min(binHeader.largeCount, binHeader.lightCount);
  for (uint i = group; i < largeCount; i += groups) {
    uint index = largeLights[i];
    uvec4 cells;
    float nearest;
    if (!lightCells(index, cells, nearest)) continue;
    uvec2 size = cells.zw - cells.xy + 1u;
    for (uint k = gl_LocalInvocationIndex; k < size.x * size.y; k += 64u) {
      uint cell = (cells.y + k / size.x) * binHeader.cellsX + cells.x + k % size.x;
      if (nearest <= uintBitsToFloat(binCells[cell].farBits)) binCell(index, cell);  // else behind
    }
  }
}

void main() {
  uint lightGroups = (binHeader.lightCount + 63u) / 64u;
  if (kLargeOnly == 1u) {
    binLargeLights(gl_WorkGroupID.x, gl_NumWorkGroups.x);
    return;
  }
  if (gl_WorkGroupID.x >= lightGroups) {  // the scatter's extra groups
    binLargeLights(gl_WorkGroupID.x - lightGroups, gl_NumWorkGroups.x - lightGroups);
    return;
  }
  uint index = gl_GlobalInvocationID.x;
  if (index >= binHeader.lightCount) return;
  uvec4 cells;
  float nearest;
  if (!lightCells(index, cells, nearest)) return;
  uvec2 size = cells.zw - cells.xy + 1u;
  if (size.x * size.y > kSmallLightCells) {
    if (kScatter == 0u) largeLights[atomicAdd(binHeader.largeCount, 1u)] = index;
    return;
  }
  for (uint y = cells.y; y <= cells.w; ++y)
    for (uint x = cells.x; x <= cells.z; ++x) {
      uint cell = y * binHeader.cellsX + x;
      if (nearest <= uintBitsToFloat(binCells[cell].farBits)) binCell(index, cell);  // else behind
    }
}
