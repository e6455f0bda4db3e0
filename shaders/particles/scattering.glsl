// How a particle scatters light: a puff of smoke or dust is not a surface, so instead of a BRDF
// it has a wrapped diffuse term (light reaches `wrap` past the terminator of a sphere-like normal:
// the soft, lit-through look of a volume) plus back lighting (light behind the particle shining
// through towards the eye, narrowed by `focus`: the bright rim of smoke in front of a lamp).
//   radiance = albedo / pi * E * (max(n.l + wrap, 0) / (1 + wrap) + back * max(-v.l, 0)^focus)
// E is the light's intensity with KHR_lights_punctual attenuation, exactly as surfaces get it.
// Pixel lighting uses the normal of a sphere under the quad; vertex lighting the normal facing the
// camera. The lit templates sum it over the technique's lights (particles/scatter_lights.glsl).
#ifndef LLL_PARTICLE_SCATTERING_GLSL
#define LLL_PARTICLE_SCATTERING_GLSL
#include "common/brdf.glsl"
#include "common/sun_shadow.glsl"
#include "particles/particle_data.glsl"

// Light one light sends towards the eye per unit albedo, from a particle at `position`.
vec3 scatterLight(GpuLight light, vec3 position, vec3 normal, vec3 towardEye) {
  vec3 toLight = light.positionRange.xyz - position;
  float distance = length(toLight);
  if (distance >= light.positionRange.w) return vec3(0.0);
  vec3 l = toLight / max(distance, 1e-6);
  // The shadow at the particle itself: no surface, so no normal offset.
  float attenuation = shadowedAttenuation(light, position, vec3(0.0), toLight, l, distance);
  if (attenuation <= 0.0) return vec3(0.0);
  float wrap = system.shading.x;
  float diffuse = max(dot(normal, l) + wrap, 0.0) / (1.0 + wrap);
  float back = system.shading.y * pow(max(dot(-towardEye, l), 0.0), system.shading.z);
  return light.colorIntensity.rgb * (light.colorIntensity.w * attenuation * (diffuse + back) / kPi);
}

// Light the directional lights (the sun) send towards the eye per unit albedo from a particle at
// `position`: as a point light's, with the illuminance in place of intensity times attenuation; the
// first, which casts the shadow, is shadowed at the particle's centre (no normal offset: a puff has
// no surface).
vec3 scatterDirectionalLights(vec3 position, vec3 normal, vec3 towardEye) {
  vec3 sum = vec3(0.0);
  float wrap = system.shading.x;
  for (uint i = 0u; i < frame.display.z; ++i) {
    vec3 l = frame.sunDirection[i].xyz;
    float diffuse = max(dot(normal, l) + wrap, 0.0) / (1.0 + wrap);
    float back = system.shading.y * pow(max(dot(-towardEye, l), 0.0), system.shading.z);
    float visible = i == 0u ? sunVisibility(position, vec3(0.0)) : 1.0;
    sum += frame.sunIlluminance[i].rgb * ((diffuse + back) * visible / kPi);
  }
  return sum;
}

// The camera's axes in world space: quads lie in the plane of `right` and `up`, `back` faces the eye.
vec3 cameraRight() {
  return vec3(frame.view[0][0], frame.view[1][0], frame.view[2][0]);
}
vec3 cameraUp() {
  return vec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
}
vec3 cameraBack() {
  return vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);
}

#endif
