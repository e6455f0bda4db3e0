#version 460
#define LLL_BINS_FAR_WRITE
#define LLL_FILL_PASS
// Nearest and farthest linear depth of each tile (common/tile_depth_range.glsl): the fills test
// lights against the tile's volume up to its farthest surface, and sliced lists (--lll-slices) split
// its range. The workgroup's 8x8 tiles are one cell of the light bins (common/light_bins.glsl): it
// also writes the cell's farthest depth, which the binning tests lights against (the dispatch is
// the grid of cells).
#include "common/light_bins.glsl"
#include "common/lll_data.glsl"
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
