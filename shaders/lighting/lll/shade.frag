#version 460
// Shading with the light linked list on the geometry: each fragment walks its tile's list. Used for
// glass (blended, at its own depth) always, and for opaque surfaces with --lll-shade fragment.
#include "common/mesh_fragment.glsl"
#include "lighting/lll/shade.glsl"

layout(location = 0) out vec4 outColor;
// No depth writes and no side effects: shade only what the prepass left visible.
layout(early_fragment_tests) in;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  bool opaque;
  vec3 color =
      shadeSurface(s, uvec2(gl_FragCoord.xy), linearizeDepth(gl_FragCoord.z), ambientAndEmissive(s), opaque);
  float alpha = m.flags.x == kAlphaBlend && !opaque ? s.alpha : 1.0;
  outColor = vec4(color * alpha, alpha);
}
