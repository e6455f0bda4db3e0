#version 460
// particles-bin's first step: the nearest view depth each tile's particle pixels fade against (the
// nearest glass or opaque surface, particlePixelDepth as the composite reads it), for the count
// pass's optical depth bound. One workgroup per tile, one invocation per particle pixel.
#define PARTICLE_TILE_NEAREST writeonly
#include "particles/tiles.glsl"

layout(local_size_x = kParticleTileSize, local_size_y = kParticleTileSize) in;
// The depth the composite fades the particles in front of the glass against: with glass in the
// scene its depth (glass drawn into the opaque depth), else the opaque depth.
layout(set = 0, binding = 16) uniform sampler2D fadeDepth;

shared uint nearestBits;  // a positive float's bits order as the float does

void main() {
  if (gl_LocalInvocationIndex == 0u) nearestBits = floatBitsToUint(3.4e38);
  barrier();
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(pixel, ivec2(tileHeader.layerWidth, tileHeader.layerHeight))))
    atomicMin(nearestBits, floatBitsToUint(max(particlePixelDepth(fadeDepth, pixel), 0.0)));
  barrier();
  if (gl_LocalInvocationIndex == 0u)
    tileNearest[gl_WorkGroupID.y * tileHeader.tilesX + gl_WorkGroupID.x] = uintBitsToFloat(nearestBits);
}
