// The fragment stage of a mesh pass: what common/mesh.vert interpolates, and the material's surface
// at the fragment.
#ifndef LLL_MESH_FRAGMENT_GLSL
#define LLL_MESH_FRAGMENT_GLSL
#include "common/material.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;

Surface surfaceAtFragment(GpuMaterial m) {
  return sampleSurface(m, inWorldPosition, inNormal, inTangent, inUv, inUv1, inColor, gl_FrontFacing);
}

#endif
