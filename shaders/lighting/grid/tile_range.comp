#version 460
#define LLL_BINS_FAR_WRITE
#define GRID_BUILD_PASS
// Nearest and farthest linear depth of each tile's opaque surfaces (common/tile_depth_range.glsl;
// the clusters split this range). The workgroup's 8x8 tiles are one cell of the light bins: it also
// writes the cell's farthest depth, which the binning tests lights against.
#include "common/grid_data.glsl"
#include "common/light_bins.glsl"
#include "common/tile_depth_range.glsl"

layout(local_size_x = kCellThreads) in;  // one workgroup a cell of 8x8 tiles
layout(set = 0, binding = 9) uniform sampler2D sceneDepth;

void main() {
  reduceCellTileDepths(sceneDepth);
}
