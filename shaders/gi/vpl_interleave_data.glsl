// What the interleaved VPL shading and its filter agree on (gi/interleaved_vpls.glsl,
// gi/vpl_filter.comp): the pattern, the albedo key, the normal's and the specular light's encodings.
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

// RGB as a shared-exponent 9:9:9:5 number (the layout of VK_FORMAT_E5B9G9R9_UFLOAT_PACK32, from
// EXT_texture_shared_exponent), for light >= 0: each channel a 9-bit fraction of the largest one's
// power of two, so a channel is exact to 1/512 of the brightest. The filter's samples carry their
// specular light so, to fit one 16-byte texel with the diffuse light as halves.
uint packRgb9e5(vec3 rgb) {
  vec3 c = clamp(rgb, vec3(0.0), vec3(65408.0));  // 511/512 * 2^16, the largest
  float largest = max(max(c.r, c.g), max(c.b, 1e-30));
  int exponent = max(-16, int(floor(log2(largest)))) + 16;  // biased by 15, plus one
  float scale = exp2(float(exponent - 24));                 // 2^(exponent - 15 - 9)
  if (floor(largest / scale + 0.5) >= 512.0) {              // rounds up to the next power
    scale *= 2.0;
    ++exponent;
  }
  uvec3 q = uvec3(min(floor(c / scale + 0.5), vec3(511.0)));
  return q.r | (q.g << 9) | (q.b << 18) | (uint(exponent) << 27);
}

vec3 unpackRgb9e5(uint v) {
  return vec3(v & 511u, (v >> 9) & 511u, (v >> 18) & 511u) * exp2(float(int(v >> 27) - 24));
}

#endif
