#version 460
#define LLL_BINS_FAR_WRITE
#define LLL_FILL_PASS
// Nearest and farthest linear depth of each tile (common/tile_depth_range.glsl): the fills test
// lights against the tile's volume up to its farthest surface, and sliced lists (--lll-slices) split
// its range. The workgroup's 8x8 tiles are one cell of the light bins (common/light_bins.glsl): it
// also writes the cell's farthest depth, which the binning tests lights against (the dispatch is
// the grid of cells). It also empties the cell's lists (every head of its tiles) and, in the first
// workgroup, the counters, for this frame's fill: a clear of its own cost a pass and a barrier.
#include "common/light_bins.glsl"
#include "common/lll_data.glsl"
#include "common/tile_depth_range.glsl"

layout(local_size_x = kCellThreads) in;  // one workgroup a cell of 8x8 tiles
layout(set = 0, binding = 9) uniform sampler2D sceneDepth;

void main() {
  uint headsPerTile = listSlices() * listClasses();
  uvec2 firstTile = gl_WorkGroupID.xy * kTileGroupSize;
  uint across = min(kTileGroupSize, frame.counts.z - firstTile.x);
  for (uint row = 0u; row < kTileGroupSize && firstTile.y + row < frame.counts.w; ++row) {
    uint first = ((firstTile.y + row) * frame.counts.z + firstTile.x) * headsPerTile;
    for (uint i = gl_LocalInvocationIndex; i < across * headsPerTile; i += kCellThreads)
      tileHeads[first + i] = kLinkEnd;
  }
  if (gl_WorkGroupID.x == 0u && gl_WorkGroupID.y == 0u && gl_LocalInvocationIndex == 0u)
    counters = LllCounters(0u, 0u, 0u, 0u);
  reduceCellTileDepths(sceneDepth);
}
