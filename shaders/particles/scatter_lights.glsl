// The light a particle scatters towards the eye from the technique's lights (its lighting
// interface, shaders/common/lighting.glsl): every light (forward), its tile's list at the
// particle's own depth (lll: a red light inside the plume tints it red), or none (unlit).
#ifndef LLL_PARTICLE_SCATTER_LIGHTS_GLSL
#define LLL_PARTICLE_SCATTER_LIGHTS_GLSL
#include "particles/scattering.glsl"

vec3 scatterLights(vec3 position, vec3 normal, vec3 towardEye, uvec2 pixel, float viewDepth) {
  vec3 sum = scatterDirectionalLights(position, normal, towardEye);
  LightCursor cursor = lightsAt(pixel, viewDepth);
  uint light;
  while (nextLight(cursor, light)) sum += scatterLight(lights[light], position, normal, towardEye);
  return sum;
}

#endif
