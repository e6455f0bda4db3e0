// The particle draw's fragment shader: a round, noisy puff on the quad, faded where it meets the
// scene (soft particles: the prepass depth, sampled) and premultiplied for BlendMode::Alpha; the
// `additive` share leaves the destination untouched, so sparks add light rather than cover it.
// With PARTICLE_LIT (lit/particles_pixel.frag) every pixel adds the technique's lights
// (particles/scatter_lights.glsl); without, the vertex shader's radiance is complete.
#include "particles/random.glsl"
#include "particles/scattering.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec2 inOffset;
layout(location = 2) in vec2 inPattern;
layout(location = 3) flat in vec4 inAlbedoOpacity;
layout(location = 4) flat in vec3 inBaseRadiance;
layout(location = 0) out vec4 outColor;
layout(set = 0, binding = 16) uniform sampler2D sceneDepth;
// Depth is only tested, never written: fragments behind the scene never run.
layout(early_fragment_tests) in;

float valueNoise(vec2 p) {
  ivec2 i = ivec2(floor(p));
  vec2 f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  float a = float(pcg3d(uvec3(i + ivec2(0, 0), 17u)).x >> 8);
  float b = float(pcg3d(uvec3(i + ivec2(1, 0), 17u)).x >> 8);
  float c = float(pcg3d(uvec3(i + ivec2(0, 1), 17u)).x >> 8);
  float d = float(pcg3d(uvec3(i + ivec2(1, 1), 17u)).x >> 8);
  return mix(mix(a, b, u.x), mix(c, d, u.x), u.y) * (1.0 / 16777216.0);
}

// Density of the puff at radius^2 r2: falls smoothly to zero at the rim, broken up by two octaves
// of noise so overlapping puffs do not read as discs.
float puffDensity(float r2, vec2 pattern) {
  float noise = 0.65 * valueNoise(pattern) + 0.35 * valueNoise(pattern * 2.3);
  return (1.0 - r2) * (1.0 - r2) * (0.45 + 0.55 * noise);
}

void main() {
  float r2 = dot(inOffset, inOffset);
  if (r2 >= 1.0) discard;
  float depth = linearizeDepth(gl_FragCoord.z);
  float sceneLinearDepth = linearizeDepth(texelFetch(sceneDepth, ivec2(gl_FragCoord.xy), 0).r);
  float fade = clamp((sceneLinearDepth - depth) / system.shading.w, 0.0, 1.0);
  float alpha = inAlbedoOpacity.a * puffDensity(r2, inPattern) * fade;
  vec3 radiance = inBaseRadiance;
#ifdef PARTICLE_LIT
  vec3 normal =
      normalize(cameraRight() * inOffset.x + cameraUp() * inOffset.y + cameraBack() * sqrt(1.0 - r2));
  vec3 towardEye = normalize(frame.cameraPosition.xyz - inWorldPosition);
  radiance +=
      inAlbedoOpacity.rgb * scatterLights(inWorldPosition, normal, towardEye, uvec2(gl_FragCoord.xy), depth);
#endif
  outColor = vec4(radiance * alpha, alpha * (1.0 - system.blend.x));
}
