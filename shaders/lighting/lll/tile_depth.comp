#version 460
#define LLL_BINS_FAR_WRITE
#define LLL_FILL_PASS
// Farthest linear depth of each tile (Bezrati 1.5.1: reduce by max, so a tile never misses a light
// that touches its farthest pixel). Edge tiles only read the pixels that exist. The workgroup's
// 8x8 tiles are one cell of the light bins (common/light_bins.glsl): it also writes the cell's
// farthest depth, which the binning tests lights against (the dispatch is the grid of cells).
#include "common/frame.glsl"
#include "common/light_bins.glsl"
#include "common/lll_data.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 9) uniform sampler2D sceneDepth;

shared uint cellFarBits;

float tileFar(uvec2 tile) {
  uint size = frame.counts.y;
  uvec2 origin = tile * size;
  uvec2 end = min(origin + uvec2(size), uvec2(frame.viewport.xy));
  float nearest = 1.0;  // reverse-Z: the smallest stored depth is the farthest surface
  for (uint y = origin.y; y < end.y; ++y)
    for (uint x = origin.x; x < end.x; ++x) nearest = min(nearest, texelFetch(sceneDepth, ivec2(x, y), 0).r);
  return linearizeDepth(nearest);
}

void main() {
  if (gl_LocalInvocationIndex == 0u) cellFarBits = 0u;
  barrier();
  uvec2 tile = gl_GlobalInvocationID.xy;
  if (tile.x < frame.counts.z && tile.y < frame.counts.w) {
    float far = tileFar(tile);
    tileDepth[tile.y * frame.counts.z + tile.x] = far;
    atomicMax(cellFarBits, floatBitsToUint(far));  // non-negative floats order like their bits
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u)
    binCells[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x].farBits = cellFarBits;
}
