// vpl-classes (--vpl-interleave where the lighting interface keeps the VPL classes apart, lll's
// class lists): workgroup (x, y) lights class y of the VPLs on the 64 pixels of slots 64x..
// (gi/every_class.glsl): the glossy metals' every class, which shade-opaque placed, and the classes
// vpl-filter found no neighbour for on the edge pixels it placed after them. A pixel's classes run
// side by side instead of one after another in a workgroup whose other pixels walk one class (H200,
// 5,144 VPLs at K = 4: shade-opaque 1.84 ms with the metals walking every class, 1.01 with no pixel
// doing so); the last of a slot's classes to finish adds them all to its pixel.
#include "common/lighting.glsl"
#include "gi/vpl_interleave_data.glsl"
#define EVERY_CLASS_LIGHT
#include "gi/every_class.glsl"

layout(local_size_x = 64) in;

layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= min(everyClass.pixels, everyClass.capacity)) return;
  EveryClassSurface e = everyClassSurfaces[slot];
  Surface s;
  s.position = e.positionDepth.xyz;
  s.view = normalize(frame.cameraPosition.xyz - s.position);
  s.normal = e.normalMetallic.xyz;
  s.alpha = 1.0;
  s.baseColor = e.baseColorRoughness.rgb;
  s.metallic = e.normalMetallic.w;
  s.roughness = e.baseColorRoughness.w;
  s.occlusion = 1.0;
  s.emissive = vec3(0.0);
  uvec2 pixel = uvec2(e.pixel.x & 0xFFFFu, e.pixel.x >> 16);
  uint vplClass = gl_WorkGroupID.y;
  if ((e.pixel.y & (1u << vplClass)) == 0u) return;  // an edge pixel that found this class
  vec3 light = lightSurfacePart(s, pixel, e.positionDepth.w, 1u + vplClass);
  everyClassLight[slot * kVplClasses + vplClass] =
      uvec2(packHalf2x16(light.rg), packHalf2x16(vec2(light.b, 0.0)));
  // The slot's classes run on workgroups of their own: the last to finish adds them all to the
  // pixel (its light written before its count, the others' read after: coherent, with barriers).
  memoryBarrierBuffer();
  uint classes = bitCount(e.pixel.y & ((1u << kVplClasses) - 1u));
  if (atomicAdd(everyClassSurfaces[slot].pixel.z, 1u) + 1u != classes) return;
  memoryBarrierBuffer();
  vec3 sum = vec3(0.0);
  for (uint c = 0u; c < kVplClasses; ++c) {
    if ((e.pixel.y & (1u << c)) == 0u) continue;
    uvec2 l = everyClassLight[slot * kVplClasses + c];
    sum += vec3(unpackHalf2x16(l.x), unpackHalf2x16(l.y).x);
  }
  imageStore(hdr, ivec2(pixel), imageLoad(hdr, ivec2(pixel)) + vec4(sum, 0.0));
}
