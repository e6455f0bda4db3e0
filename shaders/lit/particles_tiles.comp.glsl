// particles-composite (--particle-render compute): one workgroup per tile of the particles' tile
// grid, one invocation per pixel. The tile's particles come in cells, one per slab of the draw
// order, nearest first (ParticleTileHeader); consecutive cells of at most kParticleTileSharedSort
// particles together are sorted in shared memory as one run (the slabs' keys do not overlap, so
// one sort orders them all: three barriers for a run, where the edges of a plume hold many small
// cells), a longer cell's keys are marked in a bitmap of the slab's keys that is read in order;
// staged kParticleTileSize^2 at a time in shared memory and blended front to back:
//   colour += transmittance * radiance * alpha;  transmittance *= 1 - alpha * (1 - additive)
// which is the raster path's premultiplied back-to-front blend reordered, so both make the same
// image. The tile's slabs are shared out to tileHeader.groups workgroups (the z of the dispatch),
// each blending its own run into (colour, transmittance) for particles-resolve. A pixel stops once
// less than kParticleOpaqueTransmittance of the light behind it gets through, the group once all its
// pixels have, and the groups behind it once they see that (tileGroupOpaque).
// Specialization constant 0 says where the light comes from: 1 each pixel walks the technique's
// lights (pixel lighting), 2 the particle's light atlas (atlas lighting), 0 the particle's own
// radiance is complete (vertex lighting, or unlit).
#define PARTICLE_TILES_LONGEST_WRITE
#define PARTICLE_LAYERS_WRITE
#include "particles/scatter_lights.glsl"

#include "particles/tiles.glsl"

layout(local_size_x = kParticleTileSize, local_size_y = kParticleTileSize) in;
layout(constant_id = 0) const uint kLightSource = 1u;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
// In a scene with glass (Renderer::recordFrame) the composite blends two layers in one pass over the
// sorted particles: those in front of the nearest glass at the pixel (glassDepth: the opaque depth
// with the glass drawn into it), faded against the glass, into particleLayers, resolved after the
// glass; those behind it, faded against the opaque surface, into particleLayersBehind, resolved
// before the glass. Sorted nearest first, a pixel's front particles all come before its behind ones.
layout(constant_id = 50) const bool kBehindGlass = false;
layout(set = 0, binding = 25) uniform sampler2D glassDepth;
// The view depth each particle pixel was blended against (the nearest of its block of frame pixels),
// for particles-resolve below full resolution: the front layer's and the behind layer's.
layout(set = 0, binding = 24, r32f) uniform writeonly image2D particleLayerDepth;
layout(set = 0, binding = 37, r32f) uniform writeonly image2D particleLayerDepthBehind;
layout(std430, set = 0, binding = 36) writeonly buffer ParticleLayersBehindBlock {
  uvec2 particleLayersBehind[];
};

// Per tile and group: 1 once the group made every pixel of its tile opaque (cleared each frame by
// particles-bin). Groups behind it stop reading their slabs when they see it: particles-resolve
// stops at the first group that leaves a pixel opaque, so it never reads what they left, and the
// image does not depend on when they saw it.
layout(std430, set = 0, binding = 47) coherent buffer ParticleTileOpaqueBlock {
  uint tileGroupOpaque[];
};

const uint kThreads = kParticleTileSize * kParticleTileSize;

// A run's keys as read (at most kParticleTileSharedSort of them), or a long cell's as a bitmap of the
// slab's range of keys (bit k of word w: key base + 32 w + k), which holds every slab's range:
// a slab spans at most ceil(kMaxParticles / kParticleMaxSlabs) keys (checked in particle_tiles.cpp).
shared uint sortedKeys[kParticleTileBitmapWords];
// With the bitmap: the set bits before each invocation's run of words.
shared uint runRanks[kParticleTileSize * kParticleTileSize];
// A staged particle in as few bytes as its pixels read, since every pixel of the tile reads every
// staged particle from shared memory (most of the pass's time): ParticleScreen's disc, which every
// pixel tests, and look, which a covered pixel reads, and, for atlas and pixel lighting only, the
// albedo and draw order (as its bits) and the world centre and radius.
shared vec4 stagedDisc[kThreads];
shared uvec4 stagedLook[kThreads];
struct ParticleLit {
  vec4 albedoOrder;
  vec4 worldRadius;
};
shared ParticleLit stagedLit[kLightSource == 0u ? 1u : kThreads];
// The tile's cells (one per slab): each one's first entry and count, read once.
shared uint cellFirst[kParticleMaxSlabs];
shared uint cellCount[kParticleMaxSlabs];
shared uint finishedPixels;
shared uint tileParticles;  // in all the tile's cells
shared bool opaqueInFront;  // a group in front of this one made the whole tile opaque

// The first key of slab `slab` (keys k with k * slabs / visible == slab).
uint slabFirstKey(uint slab, uint slabs, uint visible) {
  return (slab * visible + slabs - 1u) / slabs;
}

// Words of the bitmap per invocation's run (at most kParticleTileBitmapWords / kThreads).
uint bitmapRun(uint words) {
  return (words + kThreads - 1u) / kThreads;
}

// Marks the cell's `count` keys from `first` in the bitmap of keys from `base` on (`words` words),
// and counts the set bits before each invocation's run (runRanks). Call it uniformly.
void markKeys(uint first, uint count, uint base, uint words) {
  for (uint w = gl_LocalInvocationIndex; w < words; w += kThreads) sortedKeys[w] = 0u;
  barrier();
  for (uint i = gl_LocalInvocationIndex; i < count; i += kThreads) {
    uint k = tileEntries[first + i] - base;
    if (k < words * 32u) atomicOr(sortedKeys[k >> 5u], 1u << (k & 31u));
  }
  barrier();
  uint run = bitmapRun(words);
  uint begin = gl_LocalInvocationIndex * run, end = min(begin + run, words);
  uint bits = 0u;
  for (uint w = begin; w < end; ++w) bits += uint(bitCount(sortedKeys[w]));
  runRanks[gl_LocalInvocationIndex] = bits;
  barrier();
  // Hillis-Steele inclusive scan of the runs' counts, then made exclusive.
  for (uint offset = 1u; offset < kThreads; offset <<= 1u) {
    uint add = gl_LocalInvocationIndex >= offset ? runRanks[gl_LocalInvocationIndex - offset] : 0u;
    barrier();
    runRanks[gl_LocalInvocationIndex] += add;
    barrier();
  }
  uint inclusive = runRanks[gl_LocalInvocationIndex];
  barrier();
  runRanks[gl_LocalInvocationIndex] = inclusive - bits;
  barrier();
}

// The key of rank `rank` (0: the nearest) in the bitmap markKeys made.
uint keyOfRank(uint rank, uint base, uint words) {
  // The last run with fewer set bits before it than `rank` + 1 holds it.
  uint low = 0u, high = kThreads - 1u;
  while (low < high) {
    uint middle = (low + high + 1u) / 2u;
    if (runRanks[middle] <= rank)
      low = middle;
    else
      high = middle - 1u;
  }
  uint left = rank - runRanks[low];
  uint run = bitmapRun(words);
  for (uint w = low * run; w < min(low * run + run, words); ++w) {
    uint word = sortedKeys[w];
    uint bits = uint(bitCount(word));
    if (left < bits) {
      for (uint i = 0u; i < left; ++i) word &= word - 1u;  // drop the lowest set bits
      return base + w * 32u + uint(findLSB(word));
    }
    left -= bits;
  }
  return base;  // not reached: the ranks count the bits
}

// Blends the `n` particles staged in shared memory into the pixel, nearest first: into `front`
// (colour, transmittance), or with glass into `behind` those behind glassViewDepth. `pixel` is in
// particle pixels, `framePixel` the frame pixel at its centre (for the lights).
void blendStaged(uint n, ivec2 pixel, uvec2 framePixel, float sceneViewDepth, float glassViewDepth,
                 inout vec4 front, inout vec4 behind, inout bool finished) {
  vec2 pixelCentre = vec2(pixel) + 0.5;
  // particleAxes(disc) is axes * disc.w: its ratio computed once, outside the loop.
  vec2 axes = vec2(1.0, particleAxisRatio());
  for (uint j = 0u; j < n && !finished; ++j) {
    // The disc first: most of a tile's particles miss most of its pixels.
    vec4 disc = stagedDisc[j];
    if (disc.z >= sceneViewDepth) continue;  // behind the scene: faded out entirely
    bool isBehind = kBehindGlass && disc.z >= glassViewDepth;
    float fadeDepth = isBehind || !kBehindGlass ? sceneViewDepth : glassViewDepth;
    vec2 offset = (pixelCentre - disc.xy) * (axes * disc.w);
    float r2 = dot(offset, offset);
    if (r2 >= 1.0) continue;
    uvec4 look = stagedLook[j];
    vec2 rotation = unpackHalf2x16(look.x), radianceRg = unpackHalf2x16(look.z);
    vec2 radianceBOpacity = unpackHalf2x16(look.w);
    // The offset turned back by the particle's rotation: where the puff's pattern is read.
    vec2 corner =
        vec2(rotation.x * offset.x + rotation.y * offset.y, rotation.x * offset.y - rotation.y * offset.x);
    float alpha = radianceBOpacity.y * puffDensity(r2, corner * 1.5 + unpackHalf2x16(look.y)) *
                  softFade(fadeDepth, disc.z);
    vec3 radiance = vec3(radianceRg, radianceBOpacity.x);
    if (kLightSource == 1u) {
      ParticleLit lit = stagedLit[j];
      vec3 world =
          lit.worldRadius.xyz + (cameraRight() * offset.x + cameraUp() * offset.y) * lit.worldRadius.w;
      radiance += lit.albedoOrder.rgb * puffLight(world, offset, r2, framePixel, disc.z);
    } else if (kLightSource == 2u) {
      ParticleLit lit = stagedLit[j];
      radiance += lit.albedoOrder.rgb * atlasLight(floatBitsToUint(lit.albedoOrder.w), offset);
    }
    vec4 layer = isBehind ? behind : front;
    layer.rgb += layer.a * radiance * alpha;
    layer.a *= 1.0 - alpha * (1.0 - system.blend.x);
    if (isBehind)
      behind = layer;
    else
      front = layer;
    // Opaque in front: nothing behind shows; opaque behind: the front particles all came before.
    if (layer.a < kParticleOpaqueTransmittance) {
      finished = true;
      atomicAdd(finishedPixels, 1u);
    }
  }
}

// Stages `s`, the particle of draw order `order`, at `slot`.
void stageParticle(uint slot, ParticleScreen s, uint order) {
  stagedDisc[slot] = s.disc;
  stagedLook[slot] = s.look;
  if (kLightSource != 0u)
    stagedLit[slot] = ParticleLit(vec4(s.albedo.rgb, uintBitsToFloat(order)), s.worldRadius);
}

// Blends a run of cells (the tile's from slab `first` on, `total` particles together, at most
// kParticleTileSharedSort) in one staging: each invocation reads one key and its particle, counts
// the run's keys below its own (a cell holds a particle once, and the slabs' keys do not overlap, so
// they differ) and stages the particle at that rank. Three barriers for the run, however many cells
// it joins. Call it uniformly.
void blendSortedRun(uint first, uint total, ivec2 pixel, uvec2 framePixel, float sceneViewDepth,
                    float glassViewDepth, uint visible, inout vec4 front, inout vec4 behind,
                    inout bool finished) {
  uint i = gl_LocalInvocationIndex;
  uint key = 0u;
  ParticleScreen s;
  if (i < total) {
    uint cell = first, offset = i;
    while (offset >= cellCount[cell]) offset -= cellCount[cell++];
    key = tileEntries[cellFirst[cell] + offset];
    sortedKeys[i] = key;
    s = particleScreen[visible - 1u - key];
  }
  barrier();
  if (i < total) {
    uint rank = 0u;
    for (uint j = 0u; j < total; ++j) rank += sortedKeys[j] < key ? 1u : 0u;
    stageParticle(rank, s, visible - 1u - key);
  }
  barrier();
  blendStaged(total, pixel, framePixel, sceneViewDepth, glassViewDepth, front, behind, finished);
  barrier();
}

// Blends one cell of more than kParticleTileSharedSort particles (slab `slab`'s) through the bitmap
// of its slab's keys, kThreads at a time, stopping once every pixel is opaque (barriers: call it
// uniformly).
void blendMarkedCell(uint slab, ivec2 pixel, uvec2 framePixel, float sceneViewDepth, float glassViewDepth,
                     uint visible, inout vec4 front, inout vec4 behind, inout bool finished) {
  uint count = cellCount[slab];
  uint slabs = tileHeader.cellsX;
  uint base = slabFirstKey(slab, slabs, visible);
  uint words = (slabFirstKey(slab + 1u, slabs, visible) - base + 31u) / 32u;
  markKeys(cellFirst[slab], count, base, words);
  for (uint start = 0u; start < count; start += kThreads) {
    uint index = start + gl_LocalInvocationIndex;
    if (index < count) {
      uint order = visible - 1u - keyOfRank(index, base, words);
      stageParticle(gl_LocalInvocationIndex, particleScreen[order], order);
    }
    barrier();
    blendStaged(min(kThreads, count - start), pixel, framePixel, sceneViewDepth, glassViewDepth, front,
                behind, finished);
    barrier();
    if (finishedPixels == kThreads) return;  // read between two barriers: the same in every invocation
  }
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

void main() {
  uint tile = gl_WorkGroupID.y * tileHeader.tilesX + gl_WorkGroupID.x;
  uint slabs = tileHeader.cellsX;  // at most kParticleMaxSlabs <= kThreads
  uint group = gl_WorkGroupID.z;
  if (gl_LocalInvocationIndex == 0u) {
    finishedPixels = 0u;
    opaqueInFront = false;
    tileParticles = 0u;
  }
  barrier();
  // Every cell of the tile (group 0 counts the longest for the stats: an atomic only where the
  // value read, perhaps stale, never above the true one, does not already hold it).
  if (gl_LocalInvocationIndex < slabs) {
    uvec2 range = particleTileRange(tile * slabs + gl_LocalInvocationIndex);
    cellFirst[gl_LocalInvocationIndex] = range.x;
    cellCount[gl_LocalInvocationIndex] = range.y;
    if (range.y > 0u) atomicAdd(tileParticles, range.y);
    if (group == 0u && range.y > tileHeader.longest) atomicMax(tileHeader.longest, range.y);
  }
  barrier();
  // The tile's groups: one per kParticlesPerTileGroup of its particles, up to the dispatch's. The
  // rest write nothing and say so (kTileGroupUnused), so particles-merge skips them.
  uint groups =
      clamp((tileParticles + kParticlesPerTileGroup - 1u) / kParticlesPerTileGroup, 1u, tileHeader.groups);
  if (group >= groups) {
    if (gl_LocalInvocationIndex == 0u) {
      tileGroupOpaque[tile * tileHeader.groups + group] = kTileGroupUnused;
      atomicAdd(tileHeader.unused, 1u);
    }
    return;  // the same in every invocation
  }
  ivec2 pixel = ivec2(gl_WorkGroupID.xy * kParticleTileSize + gl_LocalInvocationID.xy);
  uint scale = tileHeader.scale;
  bool inside = all(lessThan(pixel, ivec2(tileHeader.layerWidth, tileHeader.layerHeight)));
  uvec2 framePixel = min(uvec2(pixel) * scale + scale / 2u, uvec2(frame.viewport.xy) - 1u);
  float sceneViewDepth = inside ? particlePixelDepth(sceneDepth, pixel) : 0.0;
  float glassViewDepth = inside && kBehindGlass ? particlePixelDepth(glassDepth, pixel) : 0.0;
  bool finished = !inside;
  if (finished) atomicAdd(finishedPixels, 1u);
  barrier();
  uint visible = particleCounters.dispatch.w;
  vec4 front = vec4(0.0, 0.0, 0.0, 1.0), behind = vec4(0.0, 0.0, 0.0, 1.0);
  uint slab = group * slabs / groups, endSlab = (group + 1u) * slabs / groups;
  while (slab < endSlab && finishedPixels < kThreads) {
    if (group > 0u) {
      if (gl_LocalInvocationIndex == 0u) {
        bool seen = false;
        for (uint g = 0u; g < group && !seen; ++g)
          seen = tileGroupOpaque[tile * tileHeader.groups + g] == kTileGroupOpaque;
        opaqueInFront = seen;
        if (seen) atomicAdd(tileHeader.stopped, 1u);
      }
      barrier();
      if (opaqueInFront) break;  // the same in every invocation
    }
    // The cells from `slab` on that together hold at most kParticleTileSharedSort particles are
    // sorted and blended as one; a longer cell goes through the bitmap. The same in every invocation.
    uint total = cellCount[slab], last = slab + 1u;
    if (total > kParticleTileSharedSort) {
      blendMarkedCell(slab, pixel, framePixel, sceneViewDepth, glassViewDepth, visible, front, behind,
                      finished);
    } else {
      while (last < endSlab && total + cellCount[last] <= kParticleTileSharedSort) total += cellCount[last++];
      if (total > 0u)
        blendSortedRun(slab, total, pixel, framePixel, sceneViewDepth, glassViewDepth, visible, front, behind,
                       finished);
    }
    slab = last;
    barrier();
  }
  if (gl_LocalInvocationIndex == 0u && finishedPixels == kThreads)
    tileGroupOpaque[tile * tileHeader.groups + group] = kTileGroupOpaque;
  // Stopped for a group in front: particles-resolve never reads this group here.
  if (!inside || (group > 0u && opaqueInFront)) return;
  uint index = particleLayerIndex(group, pixel);
  particleLayers[index] = uvec2(packHalf2x16(front.rg), packHalf2x16(front.ba));
  if (kBehindGlass) particleLayersBehind[index] = uvec2(packHalf2x16(behind.rg), packHalf2x16(behind.ba));
  if (group == 0u && scale > 1u) {
    imageStore(particleLayerDepth, pixel, vec4(kBehindGlass ? glassViewDepth : sceneViewDepth));
    if (kBehindGlass) imageStore(particleLayerDepthBehind, pixel, vec4(sceneViewDepth));
  }
}
