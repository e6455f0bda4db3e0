#version 460
// Light pre-pass step 1 (Resistance 2): depth and normals. The full view-space normal is stored,
// never x and y with z rebuilt (under perspective a visible surface's view-space z can be either
// sign: the seed's "viewspace normal myth"), with the roughness the light pass's specular lobe
// needs beside it.
//   normal buffer RGBA16F: xyz view-space unit normal (facing the viewer), w roughness
#include "common/material.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 0) out vec4 outNormal;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = sampleSurface(m, inWorldPosition, inNormal, inUv, gl_FrontFacing);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  outNormal = vec4(mat3(frame.view) * s.normal, s.roughness);
}
