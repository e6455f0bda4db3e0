// particles-composite (--particle-render compute): one workgroup per tile of the particles' tile
// grid, one invocation per pixel. The tile's particles are sorted nearest first (in shared memory,
// or in the tile's own range of tileEntries when there are more than kParticleTileSharedSort),
// staged kParticleTileSize^2 at a time in shared memory, and blended front to back:
//   colour += transmittance * radiance * alpha;  transmittance *= 1 - alpha * (1 - additive)
// which is the raster path's premultiplied back-to-front blend reordered, so both make the same
// image. A pixel stops once less than kOpaqueTransmittance of the light behind it gets through,
// the tile once all its pixels have; then colour + transmittance * scene replaces the scene.
// Specialization constant 0 says where the light comes from: 1 each pixel walks the technique's
// lights (pixel lighting), 2 the particle's light atlas (atlas lighting), 0 the particle's own
// radiance is complete (vertex lighting, or unlit).
#define PARTICLE_TILES_SORT_WRITE
#include "particles/scatter_lights.glsl"

#include "particles/tiles.glsl"

layout(local_size_x = kParticleTileSize, local_size_y = kParticleTileSize) in;
layout(constant_id = 0) const uint kLightSource = 1u;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
layout(set = 0, binding = 21, rgba16f) uniform image2D hdr;

const uint kThreads = kParticleTileSize * kParticleTileSize;
// The error this leaves is at most this share of what lies behind the pixel: far below the fp16
// target's own rounding of the raster path's blends.
const float kOpaqueTransmittance = 1.0 / 1024.0;

shared uint sortedKeys[kParticleTileSharedSort];
shared ParticleScreen staged[kThreads];
shared uint stagedOrder[kThreads];
shared uint finishedPixels;

// The pair (a < b) that comparison `i` of one step of a bitonic sort compares, for blocks of `k`
// and distance `j` (j == k / 2: the step that compares mirrored elements, so every block ends
// sorted ascending and elements past the count can stay where they are as if infinite).
uvec2 bitonicPair(uint i, uint k, uint j) {
  if (j == k / 2u) {
    uint base = (i / j) * k, pos = i % j;
    return uvec2(base + pos, base + k - 1u - pos);
  }
  uint a = (i / j) * 2u * j + i % j;
  return uvec2(a, a + j);
}

// Sorts sortedKeys[0, count) ascending.
void sortShared(uint count) {
  uint n = 2u;
  while (n < count) n <<= 1u;
  for (uint k = 2u; k <= n; k <<= 1u)
    for (uint j = k / 2u; j > 0u; j >>= 1u) {
      for (uint i = gl_LocalInvocationIndex; i < n / 2u; i += kThreads) {
        uvec2 ab = bitonicPair(i, k, j);
        if (ab.y < count && sortedKeys[ab.x] > sortedKeys[ab.y]) {
          uint t = sortedKeys[ab.x];
          sortedKeys[ab.x] = sortedKeys[ab.y];
          sortedKeys[ab.y] = t;
        }
      }
      barrier();
    }
}

// Sorts tileEntries[first, first + count) ascending, the same network in device memory.
void sortInPlace(uint first, uint count) {
  uint n = 2u;
  while (n < count) n <<= 1u;
  for (uint k = 2u; k <= n; k <<= 1u)
    for (uint j = k / 2u; j > 0u; j >>= 1u) {
      for (uint i = gl_LocalInvocationIndex; i < n / 2u; i += kThreads) {
        uvec2 ab = bitonicPair(i, k, j) + first;
        if (ab.y < first + count && tileEntries[ab.x] > tileEntries[ab.y]) {
          uint t = tileEntries[ab.x];
          tileEntries[ab.x] = tileEntries[ab.y];
          tileEntries[ab.y] = t;
        }
      }
      memoryBarrierBuffer();
      barrier();
    }
}

void main() {
  uint cell = gl_WorkGroupID.y * tileHeader.cellsX + gl_WorkGroupID.x;
  uvec2 range = particleTileRange(cell);
  if (range.y == 0u) return;  // the whole workgroup
  uint count = range.y;
  ivec2 pixel = ivec2(gl_WorkGroupID.xy * kParticleTileSize + gl_LocalInvocationID.xy);
  bool inside = all(lessThan(pixel, ivec2(frame.viewport.xy)));
  float sceneViewDepth = inside ? linearizeDepth(texelFetch(sceneDepth, pixel, 0).r) : 0.0;
  vec2 pixelCentre = vec2(pixel) + 0.5;
  if (gl_LocalInvocationIndex == 0u) {
    finishedPixels = 0u;
    atomicMax(tileHeader.largeCount, count);
  }
  bool sortedHere = count <= kParticleTileSharedSort;
  if (sortedHere) {
    for (uint i = gl_LocalInvocationIndex; i < count; i += kThreads) sortedKeys[i] = tileEntries[range.x + i];
    barrier();
    sortShared(count);
  } else {
    barrier();
    sortInPlace(range.x, count);
  }
  if (!inside) atomicAdd(finishedPixels, 1u);

  uint visible = particleCounters.dispatch.w;
  vec3 colour = vec3(0.0);
  float transmittance = 1.0;
  bool finished = !inside;
  for (uint start = 0u; start < count; start += kThreads) {
    uint index = start + gl_LocalInvocationIndex;
    if (index < count) {
      uint key = sortedHere ? sortedKeys[index] : tileEntries[range.x + index];
      stagedOrder[gl_LocalInvocationIndex] = visible - 1u - key;
      staged[gl_LocalInvocationIndex] = particleScreen[visible - 1u - key];
    }
    barrier();
    uint n = min(kThreads, count - start);
    for (uint j = 0u; j < n && !finished; ++j) {
      ParticleScreen s = staged[j];
      if (s.centre.z >= sceneViewDepth) continue;  // behind the scene: faded out entirely
      vec2 offset = (pixelCentre - s.centre.xy) * s.axes.xy;
      float r2 = dot(offset, offset);
      if (r2 >= 1.0) continue;
      // The offset turned back by the particle's rotation: where the puff's pattern is read.
      vec2 corner =
          vec2(s.axes.z * offset.x + s.axes.w * offset.y, s.axes.z * offset.y - s.axes.w * offset.x);
      float alpha = s.albedoOpacity.a * puffDensity(r2, corner * 1.5 + vec2(s.centre.w, s.baseRadiance.w)) *
                    softFade(sceneViewDepth, s.centre.z);
      vec3 radiance = s.baseRadiance.rgb;
      if (kLightSource == 1u) {
        vec3 world = s.worldRadius.xyz + (cameraRight() * offset.x + cameraUp() * offset.y) * s.worldRadius.w;
        radiance += s.albedoOpacity.rgb * puffLight(world, offset, r2, uvec2(pixel), s.centre.z);
      } else if (kLightSource == 2u) {
        radiance += s.albedoOpacity.rgb * atlasLight(stagedOrder[j], offset);
      }
      colour += transmittance * radiance * alpha;
      transmittance *= 1.0 - alpha * (1.0 - system.blend.x);
      if (transmittance < kOpaqueTransmittance) {
        finished = true;
        atomicAdd(finishedPixels, 1u);
      }
    }
    barrier();
    if (finishedPixels == kThreads) break;  // read between two barriers: the same in every invocation
  }
  if (inside) {
    vec4 scene = imageLoad(hdr, pixel);
    imageStore(hdr, pixel, vec4(colour + transmittance * scene.rgb, scene.a));
  }
}
