#version 460
#define PARTICLE_TILES_WRITE
// particles-bin's count and scatter passes (specialization constant 0: 0 counts, 1 scatters),
// kBinLanes invocations per visible particle in draw order, each taking every kBinLanes-th row of
// its tiles (the dispatch's groups, one per kParticleGroupSize particles, are kBinLanes times as
// wide). The count pass writes what the tiles need of the particle (ParticleScreen) and counts it in
// every tile its disc may cover (row by row, the tiles of the disc's chord in the row: a sixth fewer
// than its bounding box's for settled smoke); after the prefix sum (tile_scan.comp) the scatter pass
// visits the same tiles and appends its key at their cursors. At full resolution a puff covers ~55
// tiles in ~8 rows and one invocation a particle waited for each atomic in turn: 8 lanes take
// particles-bin from 0.31 to 0.19 ms for 65,536 smoke particles on the H200. Below it (fewer, larger
// tiles) the lanes cost more than they save (a million at half resolution 1.01 -> 1.23 ms), and
// ParticleSystem gives them one lane (constant 2, and 3 the group's size to match).
// Constant 1 is 1 when the particle's light was computed at its centre (particles-light).
#include "particles/tiles.glsl"

layout(constant_id = 2) const uint kBinLanes = 8u;
layout(local_size_x_id = 3) in;  // kParticleGroupSize * kBinLanes
// The count pass's group's particles' discs: each computed once (screenOf), by its first lane.
shared vec4 groupDiscs[kParticleGroupSize];
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
  uint order = gl_GlobalInvocationID.x / kBinLanes, lane = gl_GlobalInvocationID.x % kBinLanes;
  uint visible = particleCounters.dispatch.w;
  vec4 disc;
  if (kScatter == 0u) {
    uint local = gl_LocalInvocationIndex / kBinLanes;
    if (lane == 0u && order < visible) {
      ParticleScreen s = screenOf(order);
      particleScreen[order] = s;
      groupDiscs[local] = s.disc;
    }
    barrier();
    if (order >= visible) return;
    disc = groupDiscs[local];
  } else {
    if (order >= visible) return;
    disc = particleScreen[order].disc;
  }
  uvec4 tiles;
  if (!particleTiles(disc, tiles)) return;
  uint key = visible - 1u - order;
  uint slabs = tileHeader.cellsX;
  uint slab = key * slabs / visible;  // below 2^32: kMaxParticles x kParticleMaxSlabs
  for (uint y = tiles.y + lane; y <= tiles.w; y += kBinLanes) {
    // The row's tiles the disc reaches, not its whole bounding box: the disc's widest chord in the
    // row's band (conservative by a margin against rounding: a tile left out has no pixel centre the
    // composite would blend it at).
    uvec2 span = particleRowTiles(disc, y, tiles);
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
