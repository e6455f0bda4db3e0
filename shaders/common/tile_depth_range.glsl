// The nearest and farthest linear depth of a screen tile's opaque surfaces (Harada's tiled culling
// bounds; Bezrati 1.5.1 reduces to the farthest, so a tile never misses a light that touches its
// farthest pixel). Edge tiles read only the pixels that exist. Shared by lll's and the grid's
// tile-depth passes.
#ifndef LLL_TILE_DEPTH_RANGE_GLSL
#define LLL_TILE_DEPTH_RANGE_GLSL
#include "common/frame.glsl"

vec2 tileDepthRange(sampler2D sceneDepth, uvec2 tile) {
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
  return vec2(linearizeDepth(nearestDepth), linearizeDepth(farthestDepth));
}

#endif
