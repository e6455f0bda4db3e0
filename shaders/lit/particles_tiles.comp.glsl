// particles-composite (--particle-render compute): one workgroup per tile of the particles' tile
// grid, one invocation per pixel. The tile's particles come in slabs of the draw order, nearest
// first (ParticleTileHeader); each slab's are sorted nearest first (in shared memory, or in their
// own range of tileEntries when there are more than kParticleTileSharedSort), staged
// kParticleTileSize^2 at a time in shared memory, and blended front to back:
//   colour += transmittance * radiance * alpha;  transmittance *= 1 - alpha * (1 - additive)
// which is the raster path's premultiplied back-to-front blend reordered, so both make the same
// image. The tile's slabs are shared out to tileHeader.groups workgroups (the z of the dispatch),
// each blending its own run into (colour, transmittance) for particles-resolve. A pixel stops once
// less than kOpaqueTransmittance of the light behind it gets through, the group once all its
// pixels have.
// Specialization constant 0 says where the light comes from: 1 each pixel walks the technique's
// lights (pixel lighting), 2 the particle's light atlas (atlas lighting), 0 the particle's own
// radiance is complete (vertex lighting, or unlit).
#define PARTICLE_TILES_SORT_WRITE
#define PARTICLE_LAYERS_WRITE
#include "particles/scatter_lights.glsl"

#include "particles/bitonic.glsl"
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

const uint kThreads = kParticleTileSize * kParticleTileSize;
// The error this leaves is at most this share of what lies behind the pixel: far below the fp16
// target's own rounding of the raster path's blends.
const float kOpaqueTransmittance = 1.0 / 1024.0;

shared uint sortedKeys[kParticleTileSharedSort];
// A staged particle in two parts, the part every pixel reads and the part covered pixels read.
struct ParticleShape {
  vec4 centre;
  vec4 axes;
};
struct ParticleLook {
  vec4 albedoOpacity;
  vec4 baseRadiance;
  vec4 worldRadius;
  uint order;
};
shared ParticleShape stagedShape[kThreads];
shared ParticleLook stagedLook[kThreads];
shared uint finishedPixels;

// The pair (a < b) that comparison `i` of one step of a bitonic sort compares, for blocks of `k`
// and distance `j` (j == k / 2: the step that compares mirrored elements, so every block ends
// sorted ascending and elements past the count can stay where they are as if infinite).
uvec2 bitonicPair(uint i, uint k, uint j) {
  if (j == k / 2u) {
    uint base = (i / j) * k, pos = i % j;
    return uvec2(base + pos, base + k - 1u - pos);
  }
  uint a = lowerIndex(i, j);
  return uvec2(a, a + j);
}

// Puts the smaller of keys a < b first: in sortedKeys, or in tileEntries.
void orderKeys(bool inShared, uint a, uint b) {
  if (inShared) {
    uint ka = sortedKeys[a], kb = sortedKeys[b];
    if (ka > kb) {
      sortedKeys[a] = kb;
      sortedKeys[b] = ka;
    }
  } else {
    uint ka = tileEntries[a], kb = tileEntries[b];
    if (ka > kb) {
      tileEntries[a] = kb;
      tileEntries[b] = ka;
    }
  }
}

// Sorts `count` keys ascending from `first`: of sortedKeys when `inShared` (the same in every
// invocation), else of tileEntries.
void sortKeys(bool inShared, uint first, uint count) {
  uint n = 2u;
  while (n < count) n <<= 1u;
  for (uint k = 2u; k <= n; k <<= 1u)
    for (uint j = k / 2u; j > 0u; j >>= 1u) {
      for (uint i = gl_LocalInvocationIndex; i < n / 2u; i += kThreads) {
        uvec2 ab = bitonicPair(i, k, j);
        if (ab.y < count) orderKeys(inShared, first + ab.x, first + ab.y);
      }
      if (!inShared) memoryBarrierBuffer();
      barrier();
    }
}

// Blends cell `cell`'s particles into the pixel, nearest first (barriers: call it uniformly): into
// `front` (colour, transmittance), or with glass into `behind` those behind glassViewDepth.
// `pixel` is in particle pixels, `framePixel` the frame pixel at its centre (for the lights).
void blendCell(uint cell, ivec2 pixel, uvec2 framePixel, float sceneViewDepth, float glassViewDepth,
               uint visible, inout vec4 front, inout vec4 behind, inout bool finished) {
  uvec2 range = particleTileRange(cell);
  uint count = range.y;
  if (count == 0u) return;
  if (gl_LocalInvocationIndex == 0u) atomicMax(tileHeader.longest, count);
  bool sortedHere = count <= kParticleTileSharedSort;
  if (sortedHere) {
    for (uint i = gl_LocalInvocationIndex; i < count; i += kThreads) sortedKeys[i] = tileEntries[range.x + i];
    barrier();
    sortKeys(true, 0u, count);
  } else {
    sortKeys(false, range.x, count);
  }
  vec2 pixelCentre = vec2(pixel) + 0.5;
  for (uint start = 0u; start < count; start += kThreads) {
    uint index = start + gl_LocalInvocationIndex;
    if (index < count) {
      uint key = sortedHere ? sortedKeys[index] : tileEntries[range.x + index];
      uint order = visible - 1u - key;
      ParticleScreen s = particleScreen[order];
      stagedShape[gl_LocalInvocationIndex] = ParticleShape(s.centre, s.axes);
      stagedLook[gl_LocalInvocationIndex] =
          ParticleLook(s.albedoOpacity, s.baseRadiance, s.worldRadius, order);
    }
    barrier();
    uint n = min(kThreads, count - start);
    for (uint j = 0u; j < n && !finished; ++j) {
      // The shape first: most of a tile's particles miss most of its pixels.
      ParticleShape shape = stagedShape[j];
      if (shape.centre.z >= sceneViewDepth) continue;  // behind the scene: faded out entirely
      bool isBehind = kBehindGlass && shape.centre.z >= glassViewDepth;
      float fadeDepth = isBehind || !kBehindGlass ? sceneViewDepth : glassViewDepth;
      vec2 offset = (pixelCentre - shape.centre.xy) * shape.axes.xy;
      float r2 = dot(offset, offset);
      if (r2 >= 1.0) continue;
      ParticleLook look = stagedLook[j];
      // The offset turned back by the particle's rotation: where the puff's pattern is read.
      vec2 corner = vec2(shape.axes.z * offset.x + shape.axes.w * offset.y,
                         shape.axes.z * offset.y - shape.axes.w * offset.x);
      float alpha = look.albedoOpacity.a *
                    puffDensity(r2, corner * 1.5 + vec2(shape.centre.w, look.baseRadiance.w)) *
                    softFade(fadeDepth, shape.centre.z);
      vec3 radiance = look.baseRadiance.rgb;
      if (kLightSource == 1u) {
        vec3 world =
            look.worldRadius.xyz + (cameraRight() * offset.x + cameraUp() * offset.y) * look.worldRadius.w;
        radiance += look.albedoOpacity.rgb * puffLight(world, offset, r2, framePixel, shape.centre.z);
      } else if (kLightSource == 2u) {
        radiance += look.albedoOpacity.rgb * atlasLight(look.order, offset);
      }
      vec4 layer = isBehind ? behind : front;
      layer.rgb += layer.a * radiance * alpha;
      layer.a *= 1.0 - alpha * (1.0 - system.blend.x);
      if (isBehind)
        behind = layer;
      else
        front = layer;
      // Opaque in front: nothing behind shows; opaque behind: the front particles all came before.
      if (layer.a < kOpaqueTransmittance) {
        finished = true;
        atomicAdd(finishedPixels, 1u);
      }
    }
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
  ivec2 pixel = ivec2(gl_WorkGroupID.xy * kParticleTileSize + gl_LocalInvocationID.xy);
  uint scale = tileHeader.scale;
  bool inside = all(lessThan(pixel, ivec2(tileHeader.layerWidth, tileHeader.layerHeight)));
  uvec2 framePixel = min(uvec2(pixel) * scale + scale / 2u, uvec2(frame.viewport.xy) - 1u);
  float sceneViewDepth = inside ? particlePixelDepth(sceneDepth, pixel) : 0.0;
  float glassViewDepth = inside && kBehindGlass ? particlePixelDepth(glassDepth, pixel) : 0.0;
  if (gl_LocalInvocationIndex == 0u) finishedPixels = 0u;
  barrier();
  bool finished = !inside;
  if (finished) atomicAdd(finishedPixels, 1u);
  barrier();
  uint visible = particleCounters.dispatch.w;
  vec4 front = vec4(0.0, 0.0, 0.0, 1.0), behind = vec4(0.0, 0.0, 0.0, 1.0);
  uint slabs = tileHeader.cellsX;
  uint group = gl_WorkGroupID.z;
  uint firstSlab = group * slabs / tileHeader.groups, endSlab = (group + 1u) * slabs / tileHeader.groups;
  for (uint slab = firstSlab; slab < endSlab && finishedPixels < kThreads; ++slab) {
    blendCell(tile * slabs + slab, pixel, framePixel, sceneViewDepth, glassViewDepth, visible, front, behind,
              finished);
    barrier();
  }
  if (!inside) return;
  uint index = particleLayerIndex(group, pixel);
  particleLayers[index] = uvec2(packHalf2x16(front.rg), packHalf2x16(front.ba));
  if (kBehindGlass) particleLayersBehind[index] = uvec2(packHalf2x16(behind.rg), packHalf2x16(behind.ba));
  if (group == 0u && scale > 1u) {
    imageStore(particleLayerDepth, pixel, vec4(kBehindGlass ? glassViewDepth : sceneViewDepth));
    if (kBehindGlass) imageStore(particleLayerDepthBehind, pixel, vec4(sceneViewDepth));
  }
}
