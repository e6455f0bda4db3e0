#version 460
// Depth prepass for alphaMode MASK: cut out texels below the material's cutoff.
#include "common/material.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  if (materialAlpha(m, inUv) < m.alpha.x) discard;
}
