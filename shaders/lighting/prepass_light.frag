#version 460
// Light pre-pass step 2: P(light, stored properties), summed per pixel into two buffers that know
// nothing of the material. With E the light's radiance times n.l, S = E * D * V its GGX lobe at
// the stored roughness, and w = (1 - v.h)^5 the material-free part of Schlick's Fresnel
// (F = f0 + (1 - f0) * w, affine in f0):
//   diffuse.rgb  += E * (1 - w)      so (1 - F) * E sums exactly as (1 - f0) * diffuse
//   specular.rgb += S
//   specular.a   += w * (S.r + S.g + S.b)   the Fresnel-weighted lobe, kept as one number
// Base colour, metallic and f0 are applied by the combine pass (prepass_combine.frag).
#include "common/brdf.glsl"
#include "lighting/light_volume.glsl"

// False for the stencil-tested draw: its stencil op clears the light's marks for the next light,
// and a discarded fragment would leave its mark behind, so rejected pixels add zero instead.
layout(constant_id = 0) const bool kDiscardRejected = true;

layout(set = 0, binding = 6) uniform texture2D normalBuffer;

layout(location = 0) flat in uint inVolume;
layout(location = 0) out vec4 outDiffuse;
layout(location = 1) out vec4 outSpecular;

// The light's two terms at the pixel; false where it adds nothing.
bool lightTerms(LightVolume volume, ivec2 pixel, out vec4 diffuse, out vec4 specular) {
  float linearDepth = litDepth(volume, pixel);
  if (linearDepth < 0.0) return false;
  vec4 stored = texelFetch(normalBuffer, pixel, 0);
  vec3 n = normalize(stored.xyz * mat3(frame.view));  // view to world: the rotation's transpose
  vec3 position = reconstructPosition(gl_FragCoord.xy, linearDepth);
  GpuLight light = lights[volume.light.x];
  vec3 toLight = light.positionRange.xyz - position;
  float distance = length(toLight);
  vec3 l = toLight / max(distance, 1e-6);
  float nDotL = dot(n, l);
  if (distance >= light.positionRange.w || nDotL <= 0.0) return false;
  float attenuation = lightAttenuation(light, toLight, l, distance);
  vec3 irradiance = light.colorIntensity.rgb * (light.colorIntensity.w * attenuation * nDotL);
  vec3 v = normalize(frame.cameraPosition.xyz - position);
  vec3 h = normalize(l + v);
  float nDotV = max(dot(n, v), 1e-4);
  float nDotH = max(dot(n, h), 0.0);
  float fresnelWeight = pow(1.0 - clamp(dot(v, h), 0.0, 1.0), 5.0);
  float alphaRoughness = max(stored.w * stored.w, 1e-3);
  vec3 lobe = irradiance * distributionGgx(nDotH, alphaRoughness) *
              visibilitySmithGgxCorrelated(nDotL, nDotV, alphaRoughness);
  diffuse = vec4(irradiance * (1.0 - fresnelWeight), 0.0);
  specular = vec4(lobe, fresnelWeight * (lobe.r + lobe.g + lobe.b));
  return true;
}

void main() {
  vec4 diffuse = vec4(0.0), specular = vec4(0.0);
  bool lit = lightTerms(volumes[inVolume], ivec2(gl_FragCoord.xy), diffuse, specular);
  if (!lit && kDiscardRejected) discard;
  outDiffuse = diffuse;
  outSpecular = specular;
}
