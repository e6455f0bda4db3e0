// The light grid's buffers (set 0, bindings 3 to 8) and its clusters: which slice of its tile a
// depth falls in, and the depth bounds of a slice. Build passes define GRID_BUILD_PASS.
#ifndef LLL_GRID_DATA_GLSL
#define LLL_GRID_DATA_GLSL
#include "common/frame.glsl"
#include "shared/depth_slices.h"
#include "shared/grid_types.h"

#ifdef GRID_BUILD_PASS
#define GRID_ACCESS
#else
#define GRID_ACCESS readonly
#endif

layout(std430, set = 0, binding = 3) readonly buffer GridBlock {  // not uniform: see frame.glsl
  GridUniforms grid;
};
// Nearest and farthest linear depth of each tile's opaque surfaces.
layout(std430, set = 0, binding = 4) GRID_ACCESS buffer TileRangeBlock {
  vec2 tileRange[];
};
// Per cluster (tile * slices + slice): first entry in gridLights, count.
layout(std430, set = 0, binding = 5) GRID_ACCESS buffer ClusterBlock {
  uvec2 clusters[];
};
layout(std430, set = 0, binding = 6) GRID_ACCESS buffer GridLightBlock {
  uint gridLights[];
};
#ifdef GRID_BUILD_PASS
layout(std430, set = 0, binding = 7) buffer GridCounterBlock {
  GridCounters gridCounters;
};
// Per cluster: the next free entry of its range while grid-write appends.
layout(std430, set = 0, binding = 8) buffer ClusterCursorBlock {
  uint clusterCursors[];
};
#endif

uint gridSlices() {
  return grid.params.x;
}

// Clamped to the grid: helper invocations past the image's edge still read a real tile.
uint gridTileOf(uvec2 pixel) {
  uvec2 t = min(pixel / frame.counts.y, frame.counts.zw - 1u);
  return t.y * frame.counts.z + t.x;
}

// The slice of a tile with depth range `range` (nearest, farthest) that holds `depth`.
// One slice in front of the tile's opaque range, the rest across it.
uvec2 gridSliceSplit() {
  return uvec2(1u, gridSlices() - 1u);
}

uint sliceOf(vec2 range, float depth) {
  return depthSliceOf(range, depth, gridSliceSplit(), frame.depthParams.x);
}

// Depth bounds of slice `slice` of a tile with depth range `range`, widened by kGridSliceSlack.
vec2 sliceBounds(vec2 range, uint slice) {
  vec2 b = depthSliceBounds(range, slice, gridSliceSplit(), frame.depthParams.x);
  return slice == 0u ? vec2(b.x, b.y * (1.0 + kGridSliceSlack))
                     : vec2(b.x * (1.0 - kGridSliceSlack), b.y * (1.0 + kGridSliceSlack));
}

// The lights of the cluster holding a point at `viewDepth` seen through `pixel`: first and end
// entries (clamped to the capacity; past it the frame is drawn again with more room).
uvec2 clusterLightRange(uvec2 pixel, float viewDepth) {
  uint tile = gridTileOf(pixel);
  uvec2 c = clusters[tile * gridSlices() + sliceOf(tileRange[tile], viewDepth)];
  uint capacity = grid.params.y;
  return uvec2(min(c.x, capacity), min(c.x + c.y, capacity));
}

#endif
