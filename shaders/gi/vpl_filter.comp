#version 460
// Adds the interleaved VPL light (gi/interleaved_vpls.glsl) to the lit frame. For each pixel p with
// a surface, the neighbours q within k-1 pixels count where they lie on p's surface
// (gi/vpl_filter_common.glsl). Each class is averaged over its counting neighbours with tent weights
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
// Where the whole (2k-1)^2 pattern about p lies on p's surface every class counts at every offset
// and the sum is the tent-weighted sum over k*k: p then adds up vpl-filter-rows' sums down its
// column (gi/vpl_filter_rows.comp) instead of gathering, where every row centre lies on its surface
// and every row's pixels on the centre's (the chained tests).
#define EVERY_CLASS_PLACE  // the edge pixels' slots
#include "gi/every_class.glsl"
#include "gi/vpl_filter_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;
layout(set = 0, binding = 48) uniform usampler2D vplAlbedoKey;
layout(set = 0, binding = 50) uniform usampler2D vplRowSums;  // gi/vpl_filter_rows.comp

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
      uvec4 qKey = texelFetch(vplSurfaceKey, q, 0);
      if (!sampleOnSurface(q, sample_, qKey, normal, position, kNormalCos, planeTolerance)) continue;
      float w = float((far + 1 - abs(dx)) * (far + 1 - abs(dy)));
      classSum += w * sample_.rgb;
      classSpecular += w * specularOfKey(qKey);
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
    imageStore(hdr, p, imageLoad(hdr, p) + vec4(centre.rgb * key + specularOfKey(centreKey) * specular, 0.0));
    return;
  }
  if (centreKey.w >= 2u) return;  // vpl-classes lights its classes in slot w - 2 and adds them
  vec3 position = viewPosition(p, centre.w);
  float planeTolerance = kPlaneTolerance * centre.w;
  int k = int(kVplInterleave), reach = k - 1;

  // The pattern on p's surface: its rows' sums down the column.
  if (p.y >= reach && p.y + reach < size.y) {
    vec3 sum = vec3(0.0), specularSum = vec3(0.0);
    bool whole = true;
    for (int dy = -reach; dy <= reach; ++dy) {
      ivec2 q = p + ivec2(0, dy);
      uvec4 row = texelFetch(vplRowSums, q, 0);
      if (row.w == 0u ||
          (dy != 0 && !sampleOnSurface(q, texelFetch(vplIndirect, q, 0), texelFetch(vplSurfaceKey, q, 0),
                                       normal, position, kChainNormalCos, kChainPlaneTolerance * centre.w))) {
        whole = false;
        break;
      }
      float w = float(k - abs(dy));
      vec2 blueSpecularRed = unpackHalf2x16(row.y);
      sum += w * vec3(unpackHalf2x16(row.x), blueSpecularRed.x);
      specularSum += w * vec3(blueSpecularRed.y, unpackHalf2x16(row.z));
    }
    if (whole) {
      imageStore(hdr, p, imageLoad(hdr, p) + vec4((sum * key + specularSum * specular) / float(k * k), 0.0));
      return;
    }
  }

  // One class at a time (no per-class arrays: at k = 4 they spilled, 9.5 ms at 1080p on the H200):
  // along each axis a class sits at one or two offsets within k-1 pixels.
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
