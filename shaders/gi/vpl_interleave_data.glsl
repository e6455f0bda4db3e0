// What the interleaved VPL shading and its filter agree on (gi/interleaved_vpls.glsl,
// gi/vpl_filter.comp): the pattern, the albedo key and the normal's encoding.
#ifndef LLL_VPL_INTERLEAVE_DATA_GLSL
#define LLL_VPL_INTERLEAVE_DATA_GLSL

// The pattern's side k (2 to kMaxVplInterleave): k*k classes.
layout(constant_id = 33) const uint kVplInterleave = 2u;
const uint kVplClasses = kVplInterleave * kVplInterleave;

uint vplClassOfPixel(uvec2 pixel) {
  return (pixel.x % kVplInterleave) + kVplInterleave * (pixel.y % kVplInterleave);
}

// A pixel whose surface is a glossy metal evaluates every class itself: its VPL light is a spray of
// sharp view-dependent glints, which the gather would smear into blocks (the atrium's metal ball
// behind its glass). Dielectrics reflect 4% at normal incidence: their VPL light is mostly diffuse.
bool evaluatesEveryClass(float metallic, float roughness) {
  return metallic >= 0.5 && roughness <= 0.5;
}

// The diffuse light is divided by this before filtering and multiplied by the centre pixel's after:
// the base colour, kept away from zero so that a black surface's light survives the division.
vec3 albedoKey(vec3 baseColor) {
  return max(baseColor, vec3(0.05));
}

// The same for the specular light: its reflectance at normal incidence, f0 = mix(0.04, base colour,
// metallic) (common/brdf.glsl), with the albedo key for the base colour.
vec3 specularKey(vec3 albedo, float metallic) {
  return mix(vec3(0.04), albedo, metallic);
}

// A unit vector as two numbers in [-1, 1] (octahedral mapping).
vec2 octahedralEncode(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 e = n.xy;
  if (n.z < 0.0) e = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return e;
}

vec3 octahedralDecode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return normalize(n);
}

#endif
