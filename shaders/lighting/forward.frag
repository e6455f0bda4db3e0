#version 460
// Brute-force forward shading: every pixel evaluates every light. The reference for all techniques.
#include "common/mesh_fragment.glsl"

layout(location = 0) out vec4 outColor;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  vec3 color = ambientAndEmissive(s);
  uint lightCount = frame.counts.x;
  for (uint i = 0; i < lightCount; ++i) color += evaluateLight(lights[i], s);
  float alpha = m.flags.x == kAlphaBlend ? s.alpha : 1.0;
  outColor = vec4(color * alpha, alpha);
}
