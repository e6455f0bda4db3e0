#version 460
#define PARTICLE_TILES_WRITE
#define PARTICLE_TILE_LIVE_SLABS writeonly
// particles-bin's cull, between the count and the prefix sum: one workgroup per tile, one
// invocation per slab. The slabs' optical depth bounds (the count pass's sums in farBits) are
// summed front to back; a slab behind those whose sum reaches kParticleCullOpticalDepth holds
// nothing any pixel of the tile still blends, and its count is set to 0: the prefix sum gives it no
// entries, the scatter skips it and the composite reads nothing there. The slabs in front of it are
// the tile's live slabs (tileLiveSlabs), which the composite's groups share out.
#include "particles/tiles.glsl"

layout(local_size_x = kParticleMaxSlabs) in;
// 0 with --no-particle-cull: every slab is live and none is emptied.
layout(constant_id = 0) const bool kCull = true;

shared float depths[kParticleMaxSlabs];
shared uint culled;

void main() {
  uint slab = gl_LocalInvocationIndex;
  uint slabs = tileHeader.cellsX;
  uint cell = (gl_WorkGroupID.y * tileHeader.tilesX + gl_WorkGroupID.x) * slabs + slab;
  depths[slab] = kCull && slab < slabs ? float(tileCells[cell].farBits) * (1.0 / kParticleCullDepthScale) : 0.0;
  if (slab == 0u) culled = 0u;
  barrier();
  // Hillis-Steele inclusive scan over the slabs, front first.
  for (uint offset = 1u; offset < kParticleMaxSlabs; offset <<= 1u) {
    float add = slab >= offset ? depths[slab - offset] : 0.0;
    barrier();
    depths[slab] += add;
    barrier();
  }
  float inFront = slab > 0u ? depths[slab - 1u] : 0.0;
  uint tile = gl_WorkGroupID.y * tileHeader.tilesX + gl_WorkGroupID.x;
  // The last live slab: the sums rise front to back, so one slab is.
  if (slab < slabs && inFront < kParticleCullOpticalDepth &&
      (slab + 1u == slabs || depths[slab] >= kParticleCullOpticalDepth))
    tileLiveSlabs[tile] = slab + 1u;
  if (slab < slabs && inFront >= kParticleCullOpticalDepth) {
    uint count = tileCells[cell].count;
    if (count != 0u) {
      tileCells[cell].count = 0u;
      atomicAdd(culled, count);
    }
  }
  barrier();
  if (slab == 0u && culled != 0u) atomicAdd(tileHeader.culled, culled);
}
