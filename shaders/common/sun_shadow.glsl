// The sun's shadow (src/shadows/sun_shadows.h): how much of one directional light reaches a point,
// looked up in its cascaded shadow map. Every pass that lights surfaces or particles reads it
// through unlistedLight() (common/material_surface.glsl) or the particles' scattering, so every
// technique shadows the sun the same way.
#ifndef LLL_SUN_SHADOW_GLSL
#define LLL_SUN_SHADOW_GLSL
#include "common/frame.glsl"
#include "common/shadow_compare.glsl"
#include "shared/shadow_types.h"

layout(std430, set = 0, binding = 26) readonly buffer SunShadowBlock {
  SunShadow sunShadow;
};
// The cascades' depths (reverse: 1 nearest the sun), compared by common/shadow_compare.glsl.
layout(set = 0, binding = 27) uniform sampler2D sunShadowAtlas;

// The cascade covering view depth `viewDepth`: the first whose split lies beyond it.
uint sunCascade(float viewDepth) {
  uint count = sunShadow.config.x;
  uint c = 0u;
  while (c + 1u < count && viewDepth > sunShadow.splits[c]) ++c;
  return c;
}

// One comparison at `cell` (a cascade's 0..1 square; kept a half texel inside it, so that a filter
// tap never reads the next cascade's cell), filtered or of the one texel.
float sunShadowTap(uint cascade, vec2 cell, float depth, bool filtered) {
  float inset = 0.5 * sunShadow.atlas.x;
  cell = clamp(cell, vec2(inset), vec2(1.0 - inset));
  vec2 origin = vec2(float(cascade % kCascadeColumns), float(cascade / kCascadeColumns));
  vec2 at = (origin + cell) * sunShadow.atlas.zw;
  return filtered ? shadowCompareLinear(sunShadowAtlas, at, depth)
                  : shadowCompareTexel(sunShadowAtlas, at, depth);
}

// The fraction of the shadow-casting sun (the frame's first directional light) that reaches `position`, 1 lit
// to 0 shadowed. `normal` (unit, or zero for particles, which have no surface) pushes the lookup off the
// surface by a texel-sized normal offset; the depth bias grows with the slope tan(theta) of the surface to
// the sun, as a texel's depth error does: together they keep a lit surface from shadowing itself.
float sunVisibility(vec3 position, vec3 normal) {
  if (sunShadow.config.x == 0u) return 1.0;
  float viewDepth = -(frame.view * vec4(position, 1.0)).z;
  uint c = sunCascade(viewDepth);
  float texel = sunShadow.texelWorld[c];
  vec3 l = frame.sunDirection[0].xyz;
  float cosTheta = clamp(dot(normal, l), 0.05, 1.0);
  float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
  bool surface = dot(normal, normal) > 0.0;
  vec3 p = position + normal * (texel * sunShadow.bias.x);
  vec4 clip = sunShadow.cascadeViewProj[c] * vec4(p, 1.0);
  vec2 cell = clip.xy * 0.5 + 0.5;
  // Outside every cascade (beyond the last split, or off its square): the sun is not occluded.
  if (any(lessThan(cell, vec2(0.0))) || any(greaterThan(cell, vec2(1.0))) || clip.z >= 1.0) return 1.0;
  float worldBias = sunShadow.bias.z + (surface ? texel * sunShadow.bias.y * min(tanTheta, 8.0) : texel);
  // Reverse depth (1 nearest the sun): the bias moves the point towards the sun.
  float depth = clip.z + worldBias / sunShadow.bias.w;
  float resolution = sunShadow.atlas.y;
  if (sunShadow.config.z == kShadowFilterNone) {
    // The texel's centre.
    cell = (floor(cell * resolution) + 0.5) * sunShadow.atlas.x;
    return sunShadowTap(c, cell, depth, false);
  }
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) sum += sunShadowTap(c, cell + vec2(x, y) * sunShadow.atlas.x, depth, true);
  return sum * (1.0 / 9.0);
}

// As sunVisibility, only where the surface faces the frame's first directional light (elsewhere the
// BRDF gives it nothing, so there is nothing to look up); 1 without one.
float sunVisibleAt(vec3 position, vec3 normal) {
  bool facing = frame.display.z > 0u && dot(normal, frame.sunDirection[0].xyz) > 0.0;
  return facing ? sunVisibility(position, normal) : 1.0;
}

#endif
