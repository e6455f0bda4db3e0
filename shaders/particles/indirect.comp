#version 460
#define PARTICLE_WRITES_ORDER
// particles-indirect: the visible count becomes the draw's vertex count (6 a quad) and the group
// count of the per-particle lighting pass (and of the atlas lighting pass), so the CPU never reads it
// back.
#include "particles/particle_data.glsl"

layout(local_size_x = 1) in;

void main() {
  uint visible = particleCounters.dispatch.w;
  particleCounters.draw = uvec4(6u * visible, 1u, 0u, 0u);
  particleCounters.dispatch.xyz = uvec3((visible + kParticleGroupSize - 1u) / kParticleGroupSize, 1u, 1u);
  particleCounters.atlas = uvec4((visible + kParticleAtlasGroup - 1u) / kParticleAtlasGroup, 1u, 1u, 0u);
}
