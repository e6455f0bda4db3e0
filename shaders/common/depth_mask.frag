#version 460
// Depth prepass for alphaMode MASK: cut out texels below the material's cutoff.
#include "common/mesh_fragment.glsl"

void main() {
  GpuMaterial m = materials[draw.ids.x];
  if (materialAlpha(m, inUv, inUv1, inColor.a) < m.alpha.x) discard;
}
