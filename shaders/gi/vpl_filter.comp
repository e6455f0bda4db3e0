#version 460
// Adds the interleaved VPL light (gi/interleaved_vpls.glsl) to the lit frame. For each pixel p with
// a surface, the neighbours q within k-1 pixels count where they lie on p's surface: normals within
// about 37 degrees (kNormalCos), q within 5% of p's depth of p's tangent plane (kPlaneTolerance; 25
// degrees and 2% gave 40.66 against 40.76 dB, K = 2 against 1, the atrium's VPLs at 640x360 on
// lavapipe). Each class is averaged over its counting neighbours with tent weights
// (k-|dx|)(k-|dy|), which give every class the same total weight where all count; the class means
// are summed, since the classes split the VPLs between them. A class no neighbour within k-1 brings
// (p is at an edge) is looked for in the next ring out, to 2k-1 pixels (atrium, K = 4, 640x360 on
// lavapipe: 36.4 -> 37.2 dB; the wide ring for every class blurs more than it helps, 36.5); one
// not found there either: where vpl-classes runs (lll's class lists) the pixel takes a slot after
// the glossy metals' and vpl-classes lights the classes it lacks on its own surface (the atrium at
// K = 4, 1080p: 0.6% of the pixels, a third of the squared error against K = 1); else, or with
// every slot taken, it is stood for by the mean of the classes found (the sum scaled by k*k over
// their number). The diffuse sum is multiplied back by p's albedo key, the specular one by p's f0
// (gi/vpl_interleave_data.glsl). A glossy metal's pixel is no sample: one that evaluated every
// class keeps its own sum, one in a slot gets its classes from vpl-classes.
#define EVERY_CLASS_PLACE  // the edge pixels' slots
#include "gi/every_class.glsl"
#include "gi/vpl_interleave_data.glsl"
#include "shared/gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

const float kNormalCos = 0.8;
const float kPlaneTolerance = 0.05;

layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {  // see common/frame.glsl
  FrameUniforms frame;
};
layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;
// Read by texel fetches, not image loads: on the H200 the gather, 49 samples a pixel at K = 4, took
// 0.585 ms through imageLoad and 0.574 through texelFetch (bench/results/h200-2026-12-04/run5).
layout(set = 0, binding = 38) uniform sampler2D vplIndirect;
layout(set = 0, binding = 39) uniform usampler2D vplSurfaceKey;
layout(set = 0, binding = 48) uniform usampler2D vplAlbedoKey;

// The point of the view-space surface seen through pixel centre `p` at view depth `z`.
vec3 viewPosition(ivec2 p, float z) {
  vec2 ndc = (vec2(p) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  // Framebuffer y points down (the projection flips it), view-space y up.
  return vec3(ndc.x * frame.depthParams.z, -ndc.y * frame.depthParams.w, -1.0) * z;
}

// One class's samples around p: the offsets along each axis within `far` pixels whose pixel is in
// the class (`start` the smallest, offsets k apart), leaving out those within `near` pixels along
// both axes (gathered before; near < 0: none), with tent weights (far + 1 - |d|) per axis, where they
// lie on p's surface (normal within kNormalCos, within planeTolerance of p's tangent plane).
void gatherClass(ivec2 p, ivec2 size, ivec2 start, int k, int near, int far, vec3 normal, vec3 position,
                 float planeTolerance, inout vec3 classSum, inout vec3 classSpecular,
                 inout float classWeight) {
  for (int dy = start.y; dy <= far; dy += k) {
    for (int dx = start.x; dx <= far; dx += k) {
      if (abs(dx) <= near && abs(dy) <= near) continue;
      ivec2 q = p + ivec2(dx, dy);
      if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
      vec4 sample_ = texelFetch(vplIndirect, q, 0);
      if (sample_.w < 0.0) continue;
      uvec4 qKey = texelFetch(vplSurfaceKey, q, 0);
      if (qKey.w != 0u) continue;  // holds every class: no class's sample
      vec3 n = octahedralDecode(unpackSnorm2x16(qKey.x));
      if (dot(n, normal) < kNormalCos) continue;
      if (abs(dot(viewPosition(q, sample_.w) - position, normal)) > planeTolerance) continue;
      float w = float((far + 1 - abs(dx)) * (far + 1 - abs(dy)));
      classSum += w * sample_.rgb;
      classSpecular += w * vec3(unpackHalf2x16(qKey.y), unpackHalf2x16(qKey.z).x);
      classWeight += w;
    }
  }
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (p.x >= size.x || p.y >= size.y) return;
  vec4 centre = texelFetch(vplIndirect, p, 0);
  if (centre.w < 0.0) return;  // no surface, or a debug view
  uvec4 centreKey = texelFetch(vplSurfaceKey, p, 0);
  vec3 normal = octahedralDecode(unpackSnorm2x16(centreKey.x));
  uvec4 albedoKeys = texelFetch(vplAlbedoKey, p, 0);
  vec2 blueMetallic = unpackHalf2x16(albedoKeys.y);
  vec3 baseColor = vec3(unpackHalf2x16(albedoKeys.x), blueMetallic.x);
  vec3 key = albedoKey(baseColor), specular = specularKey(key, blueMetallic.y);
  if (centreKey.w == 1u) {  // it evaluated every class itself (a glossy metal)
    imageStore(hdr, p,
               imageLoad(hdr, p) +
                   vec4(centre.rgb * key +
                            vec3(unpackHalf2x16(centreKey.y), unpackHalf2x16(centreKey.z).x) * specular,
                        0.0));
    return;
  }
  if (centreKey.w >= 2u) return;  // vpl-classes lights its classes in slot w - 2 and adds them
  vec3 position = viewPosition(p, centre.w);
  float planeTolerance = kPlaneTolerance * centre.w;

  // One class at a time (no per-class arrays: at k = 4 they spilled, 9.5 ms at 1080p on the H200):
  // along each axis a class sits at one or two offsets within k-1 pixels.
  int k = int(kVplInterleave), reach = k - 1;
  ivec2 inBlock = p % k;
  vec3 sum = vec3(0.0), specularSum = vec3(0.0);
  uint found = 0u, missing = 0u;  // missing: a bit per class with no sample
  for (int cy = 0; cy < k; ++cy) {
    for (int cx = 0; cx < k; ++cx) {
      // Class (cx, cy) relative to p's place in its block: the smallest offset >= -r of a pixel in the
      // class is (cell + r + k) % k - r (the modulo's arguments > 0 for r < 2k).
      ivec2 cell = ivec2(cx, cy) - inBlock;
      vec3 classSum = vec3(0.0), classSpecular = vec3(0.0);
      float classWeight = 0.0;
      gatherClass(p, size, (cell + reach + k) % k - reach, k, -1, reach, normal, position, planeTolerance,
                  classSum, classSpecular, classWeight);
      // None on p's surface within reach (an edge): the class's next ring out, to 2k-1 pixels.
      if (classWeight == 0.0)
        gatherClass(p, size, (cell + 2 * k - 1 + k) % k - (2 * k - 1), k, reach, 2 * k - 1, normal, position,
                    planeTolerance, classSum, classSpecular, classWeight);
      if (classWeight > 0.0) {
        sum += classSum / classWeight;
        specularSum += classSpecular / classWeight;
        ++found;
      } else {
        missing |= 1u << uint(cx + k * cy);  // the pixels at p + cell are in class (cx, cy)
      }
    }
  }
  vec3 indirect = sum * key + specularSum * specular;
  // Classes missing where vpl-classes runs: the pixel takes a slot, whose missing classes
  // vpl-classes lights and adds (with every slot taken, the found classes stand for the
  // rest as below).
  bool slotted = false;
  if (kVplClassesPass && missing != 0u) {
    uint slot = atomicAdd(everyClass.pixels, 1u);
    slotted = slot < everyClass.capacity;
    if (slotted) {
      if (slot % 64u == 0u) atomicAdd(everyClass.groups, 1u);
      // The world position and normal from the view-space ones (the view's rotation is orthonormal).
      mat3 toWorld = transpose(mat3(frame.view));
      everyClassSurfaces[slot] = EveryClassSurface(
          vec4(frame.cameraPosition.xyz + toWorld * position, centre.w),
          vec4(toWorld * normal, blueMetallic.y), vec4(baseColor, uintBitsToFloat(albedoKeys.z)),
          uvec4(uint(p.x) | (uint(p.y) << 16), missing, 0u, 0u));
    }
  }
  // found >= 1: the centre counts itself.
  if (!slotted) indirect *= float(kVplClasses) / float(found);
  imageStore(hdr, p, imageLoad(hdr, p) + vec4(indirect, 0.0));
}
