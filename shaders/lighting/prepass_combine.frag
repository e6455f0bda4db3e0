#version 460
// Light pre-pass step 3: the scene again with its full material, result = C(material, sums).
// glTF's BRDF is mix(dielectric, metal, metallic) (common/brdf.glsl). With S a light's lobe, w its
// Fresnel weight, c = storedF0(metallic) and f0 = mix(0.04, base, metallic) (prepass_light.frag):
//   diffuse  = (1 - metallic) * base / pi * 0.96 * sum(E * (1 - w))                  exact
//   specular = sum(F(f0) * S) = sum((c + (1 - c) w) S) + (f0 - c) * sum((1 - w) S)
//            = specular.rgb - metallic * (1 - base) * sum((1 - w) S)
// A non-metal needs only the first sum, stored per colour channel: exact. A metal's correction is
// kept as one number and takes its colour from the first sum: exact for a single light or lights
// of one colour, an approximation where differently coloured lights overlap on a metal whose base
// colour is not white. That is the seed's limit that "very limited range of materials can be
// factored in this way" without "extra storage" (exact would need a third RGB target). Taking F
// once per pixel at n.v instead, the classic light pre-pass shortcut, drops the atrium to ~31 dB
// against forward.
#extension GL_EXT_samplerless_texture_functions : require
#include "common/mesh_fragment.glsl"
#include "lighting/prepass_terms.glsl"

layout(set = 0, binding = 3) uniform texture2D diffuseLight;
layout(set = 0, binding = 4) uniform texture2D specularLight;
// How much of the sun reaches the pixel (lighting/prepass_sun_shadow.comp), 8 bits.
layout(set = 0, binding = 5) uniform texture2D sunShadowBuffer;

layout(location = 0) out vec4 outColor;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  // An fp16 sum that overflowed reads as infinity; keep it the largest finite value so the ratio
  // below cannot become Inf / Inf.
  vec3 diffuseSum = finiteRadiance(texelFetch(diffuseLight, pixel, 0).rgb);
  vec4 specularSums = texelFetch(specularLight, pixel, 0);
  specularSums =
      vec4(finiteRadiance(specularSums.rgb), notFinite(specularSums.a) ? kHalfMax : specularSums.a);
  vec3 diffuse = (1.0 - s.metallic) * (1.0 - kDielectricF0) * s.baseColor / kPi * diffuseSum;
  float specularMean = (specularSums.r + specularSums.g + specularSums.b) / 3.0;
  vec3 metalCorrection =
      specularMean > 0.0 ? specularSums.rgb * (specularSums.a / (kMetalTermScale * specularMean)) : vec3(0.0);
  vec3 specular = max(specularSums.rgb - (1.0 - s.baseColor) * metalCorrection, vec3(0.0));
  float sunVisible = texelFetch(sunShadowBuffer, pixel, 0).r;
  outColor = vec4(unlistedLightWith(s, sunVisible) + diffuse + specular, 1.0);
}
