// What the light pre-pass's three passes agree on: the normal buffer prepass_normals.frag writes
// and prepass_light.frag reads, and the light buffers prepass_light.frag writes and
// prepass_combine.frag reads.
#ifndef LLL_PREPASS_TERMS_GLSL
#define LLL_PREPASS_TERMS_GLSL
#include "common/finite.glsl"

// Normal buffer, RG32UI (8 B/px): x the view-space unit normal, octahedral-encoded in two unorm16
// (the full sphere: under perspective a visible surface's view-space z can be either sign, the
// seed's "viewspace normal myth", so z is never rebuilt from x and y); y roughness and metallic as
// two unorm16. Light pass needs roughness for the lobe and metallic to pick its Fresnel weighting.
struct PrepassSurface {
  vec3 viewNormal;
  float roughness;
  float metallic;
};

vec2 octahedralEncode(vec3 n) {
  n /= abs(n.x) + abs(n.y) + abs(n.z);
  vec2 folded = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  return n.z >= 0.0 ? n.xy : folded;
}

vec3 octahedralDecode(vec2 e) {
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  float t = max(-n.z, 0.0);
  n.x += n.x >= 0.0 ? -t : t;
  n.y += n.y >= 0.0 ? -t : t;
  return normalize(n);
}

uvec2 packPrepassSurface(PrepassSurface s) {
  return uvec2(packUnorm2x16(octahedralEncode(s.viewNormal) * 0.5 + 0.5),
               packUnorm2x16(vec2(s.roughness, s.metallic)));
}

PrepassSurface unpackPrepassSurface(uvec2 stored) {
  vec2 material = unpackUnorm2x16(stored.y);
  return PrepassSurface(octahedralDecode(unpackUnorm2x16(stored.x) * 2.0 - 1.0), material.x, material.y);
}

// The Fresnel reflectance at normal incidence the specular buffer's colour is weighted with, from
// the pixel's metallic: 0.04 for a dielectric (exact), 1 for a metal (its lobes unweighted, so
// the one-number correction for its own f0 is small). See prepass_combine.frag.
float storedF0(float metallic) {
  return mix(0.04, 1.0, metallic);
}

// The specular buffer's alpha holds metallic * mean((1 - w) * S) times this: a lobe's (1 - w) * S
// can be far larger than what a dark metal reflects, so unscaled it would overflow fp16 before the
// image does.
const float kMetalTermScale = 1.0 / 16.0;

#endif
