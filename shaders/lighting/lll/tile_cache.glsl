// The light list walk of a compute pass whose workgroup is exactly one tile (8x8 pixels, tile 8):
// the list is read once per workgroup into shared memory, a chunk at a time (one invocation
// follows the links, which must be read one after another; then the group loads the chunk's light
// records together), and every pixel then loops over shared memory only. Per pixel, the walk of
// lll_walk.glsl reads every link and light record from memory in a chain of dependent loads.
// Every invocation of the workgroup must call shadeFromTileCache (it has barriers).
#ifndef LLL_TILE_CACHE_GLSL
#define LLL_TILE_CACHE_GLSL
#include "common/lll_walk.glsl"

const uint kTileCacheLights = 64u;  // lights per chunk: 64 x 80 B of shared memory
const uint kTileCacheInvocations = 64u;

shared GpuLight tileCacheLight[kTileCacheLights];
shared vec2 tileCacheDepth[kTileCacheLights];
shared uint tileCacheIndex[kTileCacheLights];
shared uint tileCacheCount;
shared uint tileCacheLink;
shared uint tileCacheSteps;

// The lights of `tileIndex`'s list whose depth bounds contain `viewDepth`, reflected by `s`; zero
// where `covered` is false (those invocations still take part in the loads).
vec3 shadeFromTileCache(Surface s, float viewDepth, bool covered, uint tileIndex) {
  vec3 color = vec3(0.0);
  uint invocation = gl_LocalInvocationIndex;
  if (invocation == 0u) {
    tileCacheLink = tileHeads[tileIndex];
    tileCacheSteps = 0u;
  }
  barrier();
  for (;;) {
    if (invocation == 0u) {
      uint count = 0u, link = tileCacheLink, steps = tileCacheSteps, light;
      LightLink l;
      while (count < kTileCacheLights && !isListEnd(link) && steps < longestPossibleList()) {
        l = readLink(link);
        tileCacheIndex[count] = l.light;
        tileCacheDepth[count] = vec2(l.minDepth, l.maxDepth);
        link = l.next;
        ++steps;
        ++count;
      }
      tileCacheCount = count;
      tileCacheLink = link;
      tileCacheSteps = steps;
    }
    barrier();
    uint count = tileCacheCount;
    if (count == 0u) break;  // uniform: every invocation read the same value
    for (uint i = invocation; i < count; i += kTileCacheInvocations) tileCacheLight[i] = lights[tileCacheIndex[i]];
    barrier();
    if (covered) {
      for (uint i = 0u; i < count; ++i) {
        vec2 bounds = tileCacheDepth[i];
        if (viewDepth >= bounds.x && viewDepth <= bounds.y) color += evaluateLight(tileCacheLight[i], s);
      }
    }
    barrier();  // the next chunk overwrites the cache
  }
  return color;
}

#endif
