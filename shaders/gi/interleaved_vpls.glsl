// Interleaved sampling of the virtual point lights (render/interleaved_vpls.h): the pixels of each
// k x k block of the screen split the VPLs k*k ways, each pixel evaluating only the VPLs of its
// class (a VPL's class is its place among the VPLs, which end the light array, modulo k*k), and
// gi/vpl_filter.comp adds up the classes of the neighbouring pixels that lie on the same surface.
// A shading pass that includes this stores, per pixel, the class's sum in its two lobes, each
// divided by the surface's reflectance for it (so that the filter carries light, not texture): the
// diffuse by the albedo key, the specular by f0 (0.04 on every dielectric: dividing it by the
// albedo too made the floor's texture edges the largest part of the filter's error at K = 4), and
// the keys and normal the filter compares.
#ifndef LLL_INTERLEAVED_VPLS_GLSL
#define LLL_INTERLEAVED_VPLS_GLSL
#include "common/brdf.glsl"
#include "gi/vpl_interleave_data.glsl"
#define EVERY_CLASS_PLACE
#include "gi/every_class.glsl"

layout(set = 0, binding = 38, rgba16f) uniform writeonly image2D vplIndirect;
layout(set = 0, binding = 39, rgba32ui) uniform writeonly uimage2D vplSurfaceKey;
layout(set = 0, binding = 48, rgba32ui) uniform writeonly uimage2D vplAlbedoKey;

// The light sums of one pixel: everything but the VPLs, and the VPLs of the pixel's class (their
// diffuse and specular lobes apart).
struct InterleavedSums {
  vec3 direct;
  vec3 indirect;
  vec3 indirectSpecular;
  uint pixelClass;
  uint slot;  // with pixelClass kClassesElsewhere: its slot (gi/every_class.glsl)
};

// The pixel an invocation shades (Segovia et al.'s "non-interleaved" shading of the pattern): the
// dispatch covers each class's sub-image (every k-th pixel from the class's offset) with whole 8x8
// workgroups, so every invocation of a group has the same class and skips the same lights; a
// pixel-order dispatch would mix k*k classes in each group, whose lanes then wait for each other's
// lights (InterleavedVpls::dispatch sizes the grid: group (gx, gy) serves class (gx % k, gy % k)).
uvec2 interleavedPixel(uvec2 group, uvec2 local) {
  return ((group / kVplInterleave) * kTileGroupSize + local) * kVplInterleave + group % kVplInterleave;
}

// pixelClass of a pixel that evaluates every class (evaluatesEveryClass), and of one whose classes
// vpl-classes lights (kClassesElsewhere: it walks the lights before the VPLs alone).
const uint kEveryClass = 0xFFFFFFFFu;
const uint kClassesElsewhere = 0xFFFFFFFEu;

InterleavedSums startInterleavedSums(uvec2 pixel) {
  return InterleavedSums(vec3(0.0), vec3(0.0), vec3(0.0), vplClassOfPixel(pixel), 0u);
}

// A pixel that must have every class: a slot for vpl-classes to light them in where it lights them
// (kClassesElsewhere) and one is left, else kEveryClass (it walks them all itself).
void placeEveryClassPixel(inout InterleavedSums sums, uvec2 pixel, Surface s, float viewDepth) {
  sums.pixelClass = kEveryClass;
  if (!kVplClassesPass) return;
  uint slot = atomicAdd(everyClass.pixels, 1u);
  if (slot >= everyClass.capacity) return;
  if (slot % 64u == 0u) atomicAdd(everyClass.groups, 1u);
  everyClassSurfaces[slot] = EveryClassSurface(vec4(s.position, viewDepth), vec4(s.normal, s.metallic),
                                               vec4(s.baseColor, s.roughness),
                                               uvec4(pixel.x | (pixel.y << 16), 0xFFFFFFFFu, 0u, 0u));
  sums.pixelClass = kClassesElsewhere;
  sums.slot = slot;
}

// What light `index` is to the pixel: the VPLs are the lights from `firstVpl` on (FrameUniforms'
// display.w), each in class (index - firstVpl) mod k*k; the pixel skips the other classes' without
// reading their records (all of them with kClassesElsewhere).
const uint kLightSkipped = 0u, kLightDirect = 1u, kLightIndirect = 2u;
uint interleavedRole(uint index, uint firstVpl, uint pixelClass) {
  if (index < firstVpl) return kLightDirect;
  if (pixelClass == kEveryClass) return kLightIndirect;
  return (index - firstVpl) % kVplClasses == pixelClass ? kLightIndirect : kLightSkipped;
}

// What gi/vpl_filter.comp needs of this pixel; `lit` false where it must add nothing (no surface,
// or a debug view replaced the colour): per pixel the diffuse light and view depth (vplIndirect),
// the normal, specular light and mark the gather reads of every neighbour (vplSurfaceKey: two
// reads a sample, as before the lobes were apart) and the keys only the pixel's own filtering reads
// (vplAlbedoKey: base colour, whose albedo key the filter takes, metallic, and the roughness an
// edge slot's surface needs). A pixel that evaluated every class is marked (key w 1), one
// whose classes vpl-classes lit by its slot (w 2 + slot): the filter takes its own light and
// leaves it out of its neighbours' gathers.
void storeInterleaved(uvec2 pixel, bool lit, Surface s, float viewDepth, InterleavedSums sums, mat4 view) {
  if (!lit) {
    imageStore(vplIndirect, ivec2(pixel), vec4(0.0, 0.0, 0.0, -1.0));
    imageStore(vplSurfaceKey, ivec2(pixel), uvec4(0u));
    imageStore(vplAlbedoKey, ivec2(pixel), uvec4(0u));
    return;
  }
  vec3 key = albedoKey(s.baseColor);
  vec3 normal = normalize(mat3(view) * s.normal);
  imageStore(vplIndirect, ivec2(pixel), vec4(sums.indirect / key, viewDepth));
  vec3 specular = sums.indirectSpecular / specularKey(key, s.metallic);
  imageStore(
      vplSurfaceKey, ivec2(pixel),
      uvec4(packSnorm2x16(octahedralEncode(normal)), packHalf2x16(specular.rg),
            packHalf2x16(vec2(specular.b, 0.0)),
            sums.pixelClass == kEveryClass ? 1u
                                           : (sums.pixelClass == kClassesElsewhere ? 2u + sums.slot : 0u)));
  imageStore(vplAlbedoKey, ivec2(pixel),
             uvec4(packHalf2x16(s.baseColor.rg), packHalf2x16(vec2(s.baseColor.b, s.metallic)),
                   floatBitsToUint(s.roughness), 0u));
}

#endif
