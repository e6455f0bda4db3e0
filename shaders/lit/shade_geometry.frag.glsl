// Shading on the geometry through the technique's lighting interface: glass (blended, at its own
// depth) for every technique, and opaque surfaces for forward on the geometry (the reference) and
// lll --lll-shade fragment (the chapter's forward shading, walking the lists per fragment).
#include "common/lighting.glsl"
#include "common/mesh_fragment.glsl"

layout(location = 0) out vec4 outColor;
// No depth writes and no side effects: shade only what the depth pass left visible.
layout(early_fragment_tests) in;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  bool replaced;
  vec3 color = shadePixel(s, uvec2(gl_FragCoord.xy), linearizeDepth(gl_FragCoord.z), replaced);
  float alpha = m.flags.x == kAlphaBlend && !replaced ? s.alpha : 1.0;
  outColor = vec4(color * alpha, alpha);  // premultiplied, as BlendMode::Alpha expects
}
