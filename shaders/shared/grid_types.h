// The tiled and clustered light grids' data, shared by C++ and GLSL (src/lighting/light_grid.h):
// per tile its depth range, per cluster (tile x depth slice) a range of a light index array.
#ifndef LLL_GRID_TYPES_H
#define LLL_GRID_TYPES_H
#include "shared/gpu_types.h"

LLL_NAMESPACE_BEGIN

// Depth slices per tile: slice 0 holds the lights in front of the tile's nearest opaque surface
// (for glass and particles), slices 1.. split [nearest, farthest] exponentially.
LLL_CONST(uint, kMaxGridSlices, 33u);
// Relative widening of a slice's depth bounds in the build, so a point whose depth rounds across a
// slice boundary still finds every light of its cluster.
LLL_CONST(float, kGridSliceSlack, 1e-3f);

// Written by the CPU once per frame.
struct GridUniforms {
  // x slices per tile (2 for tiled), y index capacity, z debug view, w workgroups sharing a cell.
  uvec4 params;
};
LLL_CHECK_SIZE(GridUniforms, 16);

// Written by the build, read back by the CPU.
struct GridCounters {
  uint requested;  // index entries the build asked for, also past the capacity
  uint longest;    // most lights in one cluster
  uint clustersWithLights;
  uint mismatches;  // clusters grid-write did not fill exactly as grid-count counted (expected 0)
};
LLL_CHECK_SIZE(GridCounters, 16);

LLL_NAMESPACE_END
#endif
