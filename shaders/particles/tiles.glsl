// The tiled compute renderer's data (--particle-render compute): bindings 17 to 20 beside the
// particle system's 11 to 16. Cells are the light bins' (shared/light_bins_types.h), one per tile
// and slab (ParticleTileHeader), summed in blocks by particles/tile_scan.comp.
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
#if defined(PARTICLE_LAYERS_READ_WRITE)
#define PARTICLE_LAYERS_ACCESS
#elif defined(PARTICLE_LAYERS_WRITE)
#define PARTICLE_LAYERS_ACCESS writeonly
#else
#define PARTICLE_LAYERS_ACCESS readonly
#endif
// Each tile group's blend of its slabs at each particle pixel, colour and transmittance as halves:
// group g's pixel (x, y) at (g * layerHeight + y) * layerWidth + x (particles-composite writes
// every one; with more than one group particles-merge combines them into group 0's; particles-resolve
// reads group 0's).
layout(std430, set = 0, binding = 23) PARTICLE_LAYERS_ACCESS buffer ParticleLayerBlock {
  uvec2 particleLayers[];
};

uint particleLayerIndex(uint group, ivec2 pixel) {
  return (group * tileHeader.layerHeight + uint(pixel.y)) * tileHeader.layerWidth + uint(pixel.x);
}

// ParticleScreen's offset per pixel along y over that along x, the same for every particle: the
// viewport's aspect over the projection's, negative since Vulkan's y points down.
float particleAxisRatio() {
  return frame.viewport.w / frame.viewport.z * (frame.proj[0][0] / frame.proj[1][1]);
}

// The offset on the quad per pixel along x and y of the particle whose ParticleScreen disc is `disc`.
vec2 particleAxes(vec4 disc) {
  return vec2(1.0, particleAxisRatio()) * disc.w;
}

// The tiles (first xy, last zw, inclusive) whose pixels' centres may fall inside a particle's
// disc (ParticleScreen's); false when none does, or when its quad lies outside the depth range (the
// rasterizer clips the whole quad there: it is parallel to the image plane).
bool particleTiles(vec4 disc, out uvec4 tiles) {
  tiles = uvec4(0u);
  if (disc.z < frame.depthParams.x || disc.z > frame.depthParams.y) return false;
  vec2 extent = 1.0 / abs(particleAxes(disc));
  vec2 first = floor((disc.xy - extent) / float(kParticleTileSize));
  vec2 last = floor((disc.xy + extent) / float(kParticleTileSize));
  vec2 lastTile = vec2(tileHeader.tilesX, tileHeader.tilesY) - 1.0;
  if (any(greaterThan(first, lastTile)) || any(lessThan(last, vec2(0.0)))) return false;
  tiles = uvec4(clamp(first, vec2(0.0), lastTile), clamp(last, vec2(0.0), lastTile));
  return true;
}

// The tiles of row `y` (first x, last x) that a particle's disc reaches, within `tiles` (from
// particleTiles), or an empty span (x > y). Tile (x, y) spans [x, x + 1) x [y, y + 1) times
// kParticleTileSize particle pixels; the disc is |(p - disc.xy) * particleAxes| < 1. Its chord across the
// row is widest where the row comes nearest the centre; widened by a thousandth and a hundredth of a
// pixel so rounding never leaves out a tile the composite's r2 < 1 finds a pixel in.
uvec2 particleRowTiles(vec4 disc, uint y, uvec4 tiles) {
  const float size = float(kParticleTileSize);
  vec2 scale = abs(particleAxes(disc));
  float top = float(y) * size, bottom = top + size;
  float dy = max(0.0, max(top - disc.y, disc.y - bottom)) * scale.y;
  if (dy >= 1.0) return uvec2(1u, 0u);
  float chord = sqrt(1.0 - dy * dy) / scale.x * 1.001 + 0.01;
  float first = max(floor((disc.x - chord) / size), float(tiles.x));
  float last = min(floor((disc.x + chord) / size), float(tiles.z));
  return first > last ? uvec2(1u, 0u) : uvec2(first, last);
}

#ifdef PARTICLE_TILE_BLOCKS
// particles/tile_scan.comp's sums per block of kParticleScanBlock cells: x the block's count, then
// its first entry; y the count in float.
layout(std430, set = 0, binding = 49) buffer ParticleTileBlockSumBlock {
  uvec2 tileBlockSums[];
};
#endif

// The range of tileEntries holding cell `cell`'s particles (clamped to the capacity: past it the
// frame is drawn again with more room, ParticleSystem::afterFrame).
uvec2 particleTileRange(uint cell) {
  uint first = min(tileCells[cell].first, tileHeader.capacity);
  return uvec2(first, min(tileCells[cell].count, tileHeader.capacity - first));
}

#endif
