#version 460
#define PARTICLE_TILES_WRITE
// particles-bin's count and scatter passes (specialization constant 0: 0 counts, 1 scatters), one
// thread per visible particle in draw order. The count pass writes what the tiles need of the
// particle (ParticleScreen) and counts it in every tile its disc may cover (row by row, the tiles of
// the disc's chord in the row: a sixth fewer than its bounding box's for settled smoke); after the
// prefix sum (tile_scan.comp) the scatter pass visits the same tiles and appends its key at their
// cursors.
// Constant 1 is 1 when the particle's light was computed at its centre (particles-light).
#include "particles/tiles.glsl"

layout(local_size_x = 64) in;
layout(constant_id = 0) const uint kScatter = 0u;
layout(constant_id = 1) const uint kCentreLit = 0u;

ParticleScreen screenOf(uint order) {
  uint slot = drawOrder[order].y;
  Particle p = particles[slot];
  PuffLook look = puffLook(p, slot, kCentreLit != 0u ? particleRadiance[order].rgb : vec3(0.0));
  vec3 view = (frame.view * vec4(p.positionAge.xyz, 1.0)).xyz;
  vec4 clip = frame.proj * vec4(view, 1.0);
  float depth = -view.z;
  ParticleScreen s;
  // In particle pixels (tileHeader.scale frame pixels a side).
  float scale = float(tileHeader.scale);
  // A pixel is 2 / width in NDC, and NDC = proj[0][0] * view / depth along x: the offset on the quad
  // (radius 1) per pixel (along y: particleAxes).
  s.disc = vec4((clip.xy / clip.w * 0.5 + 0.5) * frame.viewport.xy / scale, depth,
                2.0 * scale * frame.viewport.z * depth / (frame.proj[0][0] * look.radius));
  const float largestHalf = 65504.0;
  vec3 radiance = min(look.baseRadiance, vec3(largestHalf));
  s.look = uvec4(packHalf2x16(vec2(cos(p.attributes.y), sin(p.attributes.y))), packHalf2x16(look.patternSeed),
                 packHalf2x16(radiance.rg), packHalf2x16(vec2(radiance.b, look.albedoOpacity.a)));
  s.albedo = vec4(look.albedoOpacity.rgb, 0.0);
  s.worldRadius = vec4(p.positionAge.xyz, look.radius);
  return s;
}

void main() {
  uint order = gl_GlobalInvocationID.x;
  uint visible = particleCounters.dispatch.w;
  if (order >= visible) return;
  ParticleScreen s;
  if (kScatter == 0u) {
    s = screenOf(order);
    particleScreen[order] = s;
  } else {
    s = particleScreen[order];
  }
  uvec4 tiles;
  if (!particleTiles(s, tiles)) return;
  uint key = visible - 1u - order;
  uint slabs = tileHeader.cellsX;
  uint slab = key * slabs / visible;  // below 2^32: kMaxParticles x kParticleMaxSlabs
  for (uint y = tiles.y; y <= tiles.w; ++y) {
    // The row's tiles the disc reaches, not its whole bounding box: the disc's widest chord in the
    // row's band (conservative by a margin against rounding: a tile left out has no pixel centre the
    // composite would blend it at).
    uvec2 span = particleRowTiles(s, y, tiles);
    for (uint x = span.x; x <= span.y; ++x) {
      uint cell = (y * tileHeader.tilesX + x) * slabs + slab;
      if (kScatter == 0u) {
        atomicAdd(tileCells[cell].count, 1u);
      } else {
        uint slot = atomicAdd(tileCells[cell].cursor, 1u);
        if (slot < tileHeader.capacity) tileEntries[slot] = key;
      }
    }
  }
}
