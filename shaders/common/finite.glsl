// Tests for infinities and NaNs that a compiler may not fold away: by default Vulkan lets it assume
// floating-point values are neither (no SignedZeroInfNanPreserve), so isnan()/isinf() can be
// compiled to false. The exponent bits cannot.
#ifndef LLL_FINITE_GLSL
#define LLL_FINITE_GLSL

// The largest finite fp16 value: what an RGBA16F target holds at most.
const float kHalfMax = 65504.0;

bool notFinite(float x) {
  return (floatBitsToUint(x) & 0x7F800000u) == 0x7F800000u;
}

bool anyNotFinite(vec3 v) {
  return notFinite(v.x) || notFinite(v.y) || notFinite(v.z);
}

// Radiance read from an fp16 target, with an overflowed (infinite) channel taken as the largest
// finite value, so that later arithmetic (Inf / Inf, Inf * 0) cannot make a NaN of it.
vec3 finiteRadiance(vec3 c) {
  return vec3(notFinite(c.x) ? kHalfMax : c.x, notFinite(c.y) ? kHalfMax : c.y,
              notFinite(c.z) ? kHalfMax : c.z);
}

#endif
