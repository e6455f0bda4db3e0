// The particle draw's fragment shader: a round, noisy puff on the quad, faded where it meets the
// scene (soft particles: the prepass depth, sampled) and premultiplied for BlendMode::Alpha; the
// `additive` share leaves the destination untouched, so sparks add light rather than cover it.
// With PARTICLE_LIT (lit/particles_pixel.frag) every pixel adds the technique's lights
// (particles/scatter_lights.glsl); with PARTICLE_ATLAS (draw_atlas.frag) it reads the particle's
// light atlas; without either, the vertex shader's radiance is complete.
#include "particles/puff.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec2 inOffset;
layout(location = 2) in vec2 inPattern;
layout(location = 3) flat in vec4 inAlbedoOpacity;
layout(location = 4) flat in vec3 inBaseRadiance;
layout(location = 5) flat in uint inOrder;
layout(location = 0) out vec4 outColor;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
// Depth is only tested, never written: fragments behind the scene never run.
layout(early_fragment_tests) in;
// The draw before the glass (Renderer::recordFrame): only what lies behind the nearest glass at
// the pixel (glassDepth: the opaque depth with the glass drawn into it); the rest is drawn after
// the glass, against glassDepth.
layout(constant_id = 50) const bool kBehindGlass = false;
layout(set = 0, binding = 25) uniform sampler2D glassDepth;

void main() {
  float r2 = dot(inOffset, inOffset);
  if (r2 >= 1.0) discard;
  float depth = linearizeDepth(gl_FragCoord.z);
  if (kBehindGlass && depth < linearizeDepth(texelFetch(glassDepth, ivec2(gl_FragCoord.xy), 0).r)) discard;
  float sceneLinearDepth = linearizeDepth(texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r);
  float alpha = inAlbedoOpacity.a * puffDensity(r2, inPattern) * softFade(sceneLinearDepth, depth);
  vec3 radiance = inBaseRadiance;
#if defined(PARTICLE_LIT)
  radiance += inAlbedoOpacity.rgb * puffLight(inWorldPosition, inOffset, r2, uvec2(gl_FragCoord.xy), depth);
#elif defined(PARTICLE_ATLAS)
  radiance += inAlbedoOpacity.rgb * atlasLight(inOrder, inOffset);
#endif
  outColor = vec4(radiance * alpha, alpha * (1.0 - system.blend.x));
}
