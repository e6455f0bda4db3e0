#version 460
#define LLL_BINS_FAR_WRITE
#define GRID_BUILD_PASS
// Nearest and farthest linear depth of each tile's opaque surfaces (Harada's tiled culling bounds;
// the clusters split this range). The workgroup's 8x8 tiles are one cell of the light bins: it also
// writes the cell's farthest depth, which the binning tests lights against.
#include "common/grid_data.glsl"
#include "common/light_bins.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 9) uniform sampler2D sceneDepth;

shared uint cellFarBits;

void main() {
  if (gl_LocalInvocationIndex == 0u) cellFarBits = 0u;
  barrier();
  uvec2 tile = gl_GlobalInvocationID.xy;
  if (tile.x < frame.counts.z && tile.y < frame.counts.w) {
    uint size = frame.counts.y;
    uvec2 origin = tile * size;
    uvec2 end = min(origin + uvec2(size), uvec2(frame.viewport.xy));
    // Reverse-Z: the largest stored depth is the nearest surface, the smallest the farthest.
    float nearestDepth = 0.0, farthestDepth = 1.0;
    for (uint y = origin.y; y < end.y; ++y) {
      for (uint x = origin.x; x < end.x; ++x) {
        float d = texelFetch(sceneDepth, ivec2(x, y), 0).r;
        nearestDepth = max(nearestDepth, d);
        farthestDepth = min(farthestDepth, d);
      }
    }
    float far = linearizeDepth(farthestDepth);
    tileRange[tile.y * frame.counts.z + tile.x] = vec2(linearizeDepth(nearestDepth), far);
    atomicMax(cellFarBits, floatBitsToUint(far));  // non-negative floats order like their bits
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u)
    binCells[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x].farBits = cellFarBits;
}
