#version 460
// vpl-slots-add (--vpl-interleave with lll's class lists): adds to each slot's pixel the light of
// the classes vpl-classes lit on its surface (shared/every_class_types.h): every class of a glossy
// metal's pixel, which shade-opaque placed, and the classes an edge pixel lacks, which vpl-filter
// placed after adding the classes it found.
#include "shared/every_class_types.h"
#include "shared/gpu_types.h"

layout(local_size_x = 64) in;

layout(constant_id = 33) const uint kVplInterleave = 2u;
const uint kVplClasses = kVplInterleave * kVplInterleave;

layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;
layout(std430, set = 0, binding = 44) readonly buffer EveryClassHeaderBlock {
  EveryClassHeader everyClass;
};
layout(std430, set = 0, binding = 45) readonly buffer EveryClassSurfaceBlock {
  EveryClassSurface everyClassSurfaces[];
};
layout(std430, set = 0, binding = 46) readonly buffer EveryClassLightBlock {
  uvec2 everyClassLight[];  // slot * K*K + class, rgb as halves
};

void main() {
  uint slot = gl_GlobalInvocationID.x;
  if (slot >= min(everyClass.pixels, everyClass.capacity)) return;
  uvec4 pixelClasses = everyClassSurfaces[slot].pixel;
  vec3 light = vec3(0.0);
  for (uint c = 0u; c < kVplClasses; ++c) {
    if ((pixelClasses.y & (1u << c)) == 0u) continue;
    uvec2 l = everyClassLight[slot * kVplClasses + c];
    light += vec3(unpackHalf2x16(l.x), unpackHalf2x16(l.y).x);
  }
  ivec2 pixel = ivec2(pixelClasses.x & 0xFFFFu, pixelClasses.x >> 16);
  imageStore(hdr, pixel, imageLoad(hdr, pixel) + vec4(light, 0.0));
}
