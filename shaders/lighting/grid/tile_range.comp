#version 460
#define LLL_BINS_FAR_WRITE
#define GRID_BUILD_PASS
// Nearest and farthest linear depth of each tile's opaque surfaces (Harada's tiled culling bounds;
// the clusters split this range). The workgroup's 8x8 tiles are one cell of the light bins: it also
// writes the cell's farthest depth, which the binning tests lights against.
#include "common/grid_data.glsl"
#include "common/light_bins.glsl"
#include "common/tile_depth_range.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 9) uniform sampler2D sceneDepth;

shared uint cellFarBits;

void main() {
  if (gl_LocalInvocationIndex == 0u) cellFarBits = 0u;
  barrier();
  uvec2 tile = gl_GlobalInvocationID.xy;
  if (tile.x < frame.counts.z && tile.y < frame.counts.w) {
    vec2 range = tileDepthRange(sceneDepth, tile);
    tileRange[tile.y * frame.counts.z + tile.x] = range;
    atomicMax(cellFarBits, floatBitsToUint(range.y));  // non-negative floats order like their bits
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u)
    binCells[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x].farBits = cellFarBits;
}
