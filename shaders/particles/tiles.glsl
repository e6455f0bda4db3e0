// The tiled compute renderer's data (--particle-render compute): bindings 17 to 20 beside the
// particle system's 11 to 16. Cells are the light bins' (shared/light_bins_types.h), one per tile
// and slab (ParticleTileHeader), so that one prefix sum (lighting/bins/bin_scan.comp) serves both.
#ifndef LLL_PARTICLE_TILES_GLSL
#define LLL_PARTICLE_TILES_GLSL
#include "particles/puff.glsl"
#include "shared/light_bins_types.h"

// Written by particles-bin (PARTICLE_TILES_WRITE); the header also by the composite
// (PARTICLE_TILES_LONGEST_WRITE): the longest tile.
#ifdef PARTICLE_TILES_WRITE
#define PARTICLE_TILES_ACCESS
#define PARTICLE_TILES_LONGEST_WRITE
#else
#define PARTICLE_TILES_ACCESS readonly
#endif
#ifdef PARTICLE_TILES_LONGEST_WRITE
#define PARTICLE_TILES_HEADER_ACCESS
#else
#define PARTICLE_TILES_HEADER_ACCESS readonly
#endif

layout(std430, set = 0, binding = 17) PARTICLE_TILES_HEADER_ACCESS buffer ParticleTileHeaderBlock {
  ParticleTileHeader tileHeader;
};
layout(std430, set = 0, binding = 18) PARTICLE_TILES_ACCESS buffer ParticleTileCellBlock {
  LightBinCell tileCells[];
};
// Each tile's particles as keys (visible - 1 - draw order: the nearest first), in the order the
// scatter's atomics gave them (the composite puts each cell's in order).
layout(std430, set = 0, binding = 19) PARTICLE_TILES_ACCESS buffer ParticleTileEntryBlock {
  uint tileEntries[];
};
layout(std430, set = 0, binding = 20) PARTICLE_TILES_ACCESS buffer ParticleScreenBlock {
  ParticleScreen particleScreen[];
};
#ifdef PARTICLE_LAYERS_WRITE
#define PARTICLE_LAYERS_ACCESS writeonly
#else
#define PARTICLE_LAYERS_ACCESS readonly
#endif
// Each tile group's blend of its slabs at each particle pixel, colour and transmittance as halves:
// group g's pixel (x, y) at (g * layerHeight + y) * layerWidth + x (particles-composite writes
// every one, particles-resolve reads them).
layout(std430, set = 0, binding = 23) PARTICLE_LAYERS_ACCESS buffer ParticleLayerBlock {
  uvec2 particleLayers[];
};

uint particleLayerIndex(uint group, ivec2 pixel) {
  return (group * tileHeader.layerHeight + uint(pixel.y)) * tileHeader.layerWidth + uint(pixel.x);
}

// The tiles (first xy, last zw, inclusive) whose pixels' centres may fall inside the particle's
// disc; false when none does, or when its quad lies outside the depth range (the rasterizer clips
// the whole quad there: it is parallel to the image plane).
bool particleTiles(ParticleScreen s, out uvec4 tiles) {
  tiles = uvec4(0u);
  if (s.centre.z < frame.depthParams.x || s.centre.z > frame.depthParams.y) return false;
  vec2 extent = 1.0 / abs(s.axes.xy);
  vec2 first = floor((s.centre.xy - extent) / float(kParticleTileSize));
  vec2 last = floor((s.centre.xy + extent) / float(kParticleTileSize));
  vec2 lastTile = vec2(tileHeader.tilesX, tileHeader.tilesY) - 1.0;
  if (any(greaterThan(first, lastTile)) || any(lessThan(last, vec2(0.0)))) return false;
  tiles = uvec4(clamp(first, vec2(0.0), lastTile), clamp(last, vec2(0.0), lastTile));
  return true;
}

// The view depth a particle pixel blends against: the frame's, or below full resolution the
// nearest in its block (no particle shows over geometry nearer than it; the upsample sorts out the
// pixels behind).
float particlePixelDepth(sampler2D depthImage, ivec2 pixel) {
  int scale = int(tileHeader.scale);
  if (scale == 1) return linearizeDepth(texelFetch(depthImage, pixel, 0).r);
  ivec2 last = ivec2(frame.viewport.xy) - 1;
  float nearest = 3.4e38;
  for (int y = 0; y < scale; ++y)
    for (int x = 0; x < scale; ++x) {
      ivec2 p = min(pixel * scale + ivec2(x, y), last);
      nearest = min(nearest, linearizeDepth(texelFetch(depthImage, p, 0).r));
    }
  return nearest;
}

#ifdef PARTICLE_TILE_NEAREST
// Per tile: the nearest view depth any of its particle pixels fades against (the nearest glass or
// opaque surface), written by particles/tile_depth.comp for the count pass's optical depth bound.
layout(std430, set = 0, binding = 49) PARTICLE_TILE_NEAREST buffer ParticleTileNearestBlock {
  float tileNearest[];
};

// A lower bound, in units of 1 / kParticleCullDepthScale, of the optical depth particle `s` puts in
// front of every pixel of tile `tile`, whose pixels fade against depths from `nearest` on: zero
// unless its disc covers every pixel centre of the tile inside the layer in front of `nearest`.
// The composite's alpha at a pixel is opacity x puffDensity x softFade, at least opacity x
// puffDensityLowerBound at the tile's farthest pixel centre from the particle's x softFade at
// `nearest`; a pixel lets through 1 - alpha (1 - additive share) of the light behind.
uint particleTileOpticalDepth(ParticleScreen s, uvec2 tile, float nearest) {
  if (s.centre.z >= nearest) return 0u;
  uvec2 lastPixel = uvec2(tileHeader.layerWidth, tileHeader.layerHeight) - 1u;
  vec2 first = vec2(tile * kParticleTileSize) + 0.5;
  vec2 last = vec2(min(tile * kParticleTileSize + (kParticleTileSize - 1u), lastPixel)) + 0.5;
  vec2 farthest = max(abs(first - s.centre.xy), abs(last - s.centre.xy)) * abs(s.axes.xy);
  float r2 = dot(farthest, farthest);
  if (r2 >= 1.0) return 0u;
  float alpha = s.albedoOpacity.a * puffDensityLowerBound(r2) * softFade(nearest, s.centre.z) *
                (1.0 - system.blend.x);
  float depth = -log(1.0 - clamp(alpha, 0.0, 0.999));
  return uint(min(depth * kParticleCullDepthScale, float(kParticleCullDepthMost)));
}
#endif

#ifdef PARTICLE_TILE_LIVE_SLABS
// Per tile: its slabs in front of the first one cull_slabs.comp emptied (all of them when none was):
// the composite's groups share out these.
layout(std430, set = 0, binding = 50) PARTICLE_TILE_LIVE_SLABS buffer ParticleTileLiveSlabsBlock {
  uint tileLiveSlabs[];
};
#endif

// The range of tileEntries holding cell `cell`'s particles (clamped to the capacity: past it the
// frame is drawn again with more room, ParticleSystem::afterFrame).
uvec2 particleTileRange(uint cell) {
  uint first = min(tileCells[cell].first, tileHeader.capacity);
  return uvec2(first, min(tileCells[cell].count, tileHeader.capacity - first));
}

#endif
