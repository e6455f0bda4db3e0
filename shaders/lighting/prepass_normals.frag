#version 460
// Light pre-pass step 1 (Resistance 2): depth, and what the light pass needs of each pixel's
// surface: its normal, roughness and metallic (the layout is in lighting/prepass_terms.glsl).
#include "common/mesh_fragment.glsl"
#include "lighting/prepass_terms.glsl"

layout(location = 0) out uvec2 outSurface;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  outSurface = packPrepassSurface(PrepassSurface(mat3(frame.view) * s.normal, s.roughness, s.metallic));
}
