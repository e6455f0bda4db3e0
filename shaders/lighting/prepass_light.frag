#version 460
// Light pre-pass step 2: P(light, stored properties), summed per pixel into two buffers that know
// nothing of the material's colour. With E the light's radiance times n.l, S = E * D * V its GGX
// lobe at the stored roughness, w = (1 - v.h)^5 the material-free part of Schlick's Fresnel
// (F = f0 + (1 - f0) * w, affine in f0) and c = storedF0(metallic) (prepass_terms.glsl):
//   diffuse.rgb  += E * (1 - w)                the dielectric diffuse: 1 - F(0.04) = 0.96 * (1 - w)
//   specular.rgb += S * (c + (1 - c) * w)      exact for every non-metal (c = 0.04), and of the
//                                              size the final image has, so fp16 overflows where
//                                              forward's target does
//   specular.a   += metallic * mean((1 - w) * S) * kMetalTermScale   a metal's correction for its f0
// The combine pass (prepass_combine.frag) applies base colour, metallic and f0.
#include "common/brdf.glsl"
#include "lighting/light_volume.glsl"
#include "lighting/prepass_terms.glsl"

// False for the stencil-tested draw: its stencil op clears the light's marks for the next light,
// and a discarded fragment would leave its mark behind, so rejected pixels add zero instead.
layout(constant_id = 0) const bool kDiscardRejected = true;

layout(set = 0, binding = 6) uniform utexture2D surfaceBuffer;

layout(location = 0) flat in uint inVolume;
layout(location = 0) out vec4 outDiffuse;
layout(location = 1) out vec4 outSpecular;

// The light's two terms at the pixel; zero where it adds nothing. The stencil-tested pipeline
// writes whatever this returns (it cannot discard), so every path returns a defined value.
struct LightTerms {
  vec4 diffuse;
  vec4 specular;
};

LightTerms lightTerms(LightVolume volume, ivec2 pixel) {
  LightTerms terms = LightTerms(vec4(0.0), vec4(0.0));
  float linearDepth = litDepth(volume, pixel);
  if (linearDepth < 0.0) return terms;
  PrepassSurface stored = unpackPrepassSurface(texelFetch(surfaceBuffer, pixel, 0).xy);
  vec3 n = normalize(stored.viewNormal * mat3(frame.view));  // view to world: the rotation's transpose
  vec3 position = reconstructPosition(gl_FragCoord.xy, linearDepth);
  GpuLight light = lights[volume.light.x];
  vec3 toLight = light.positionRange.xyz - position;
  float distance = length(toLight);
  vec3 l = toLight / max(distance, 1e-6);
  float nDotL = dot(n, l);
  if (distance >= light.positionRange.w || nDotL <= 0.0) return terms;
  float attenuation = shadowedAttenuation(light, position, n, toLight, l, distance);
  vec3 irradiance = light.colorIntensity.rgb * (light.colorIntensity.w * attenuation * nDotL);
  vec3 v = normalize(frame.cameraPosition.xyz - position);
  vec3 h = halfVector(l, v);
  float nDotV = max(dot(n, v), 1e-4);
  float nDotH = max(dot(n, h), 0.0);
  float fresnelWeight = pow(1.0 - clamp(dot(v, h), 0.0, 1.0), 5.0);
  float alphaRoughness = max(stored.roughness * stored.roughness, 1e-3);
  // A virtual point light's lobe is wider than the surface's (common/brdf.glsl).
  float distributionAlpha = lightDistributionAlpha(light, alphaRoughness, 1.0 / max(distance, 1e-6));
  vec3 lobe = irradiance * distributionGgx(nDotH, distributionAlpha) *
              visibilitySmithGgxCorrelated(nDotL, nDotV, alphaRoughness);
  float c = storedF0(stored.metallic);
  terms.diffuse = vec4(irradiance * (1.0 - fresnelWeight), 0.0);
  terms.specular =
      vec4(lobe * (c + (1.0 - c) * fresnelWeight),
           stored.metallic * (1.0 - fresnelWeight) * (lobe.r + lobe.g + lobe.b) * (kMetalTermScale / 3.0));
  return terms;
}

void main() {
  LightTerms terms = lightTerms(volumes[inVolume], ivec2(gl_FragCoord.xy));
  if (kDiscardRejected && terms.diffuse == vec4(0.0) && terms.specular == vec4(0.0)) discard;
  outDiffuse = terms.diffuse;
  outSpecular = terms.specular;
}
