// Curl noise (Bridson, Hourihan and Nordenstam 2007): the curl of a smooth vector potential is a
// divergence-free velocity field, so particles swirl without bunching up or thinning out. The
// potential's three components are quintic value noise with analytic derivatives (Quilez), two
// octaves, on a lattice hashed with pcg3d.
#ifndef LLL_PARTICLE_CURL_NOISE_GLSL
#define LLL_PARTICLE_CURL_NOISE_GLSL
#include "particles/random.glsl"

float latticeValue(ivec3 cell, uint field) {
  return float(pcg3d(uvec3(cell) + uvec3(field * 7919u, field * 104729u, field * 1299709u)).x >> 8) *
             (2.0 / 16777216.0) -
         1.0;
}

// x: noise value in [-1, 1]; yzw: its gradient.
vec4 valueNoiseWithGradient(vec3 x, uint field) {
  ivec3 i = ivec3(floor(x));
  vec3 w = fract(x);
  vec3 u = w * w * w * (w * (w * 6.0 - 15.0) + 10.0);
  vec3 du = 30.0 * w * w * (w * (w - 2.0) + 1.0);
  float a = latticeValue(i + ivec3(0, 0, 0), field);
  float b = latticeValue(i + ivec3(1, 0, 0), field);
  float c = latticeValue(i + ivec3(0, 1, 0), field);
  float d = latticeValue(i + ivec3(1, 1, 0), field);
  float e = latticeValue(i + ivec3(0, 0, 1), field);
  float f = latticeValue(i + ivec3(1, 0, 1), field);
  float g = latticeValue(i + ivec3(0, 1, 1), field);
  float h = latticeValue(i + ivec3(1, 1, 1), field);
  float k1 = b - a, k2 = c - a, k3 = e - a;
  float k4 = a - b - c + d, k5 = a - c - e + g, k6 = a - b - e + f;
  float k7 = -a + b + c - d + e - f - g + h;
  float value = a + k1 * u.x + k2 * u.y + k3 * u.z + k4 * u.x * u.y + k5 * u.y * u.z + k6 * u.z * u.x +
                k7 * u.x * u.y * u.z;
  vec3 gradient =
      du * vec3(k1 + k4 * u.y + k6 * u.z + k7 * u.y * u.z, k2 + k5 * u.z + k4 * u.x + k7 * u.z * u.x,
                k3 + k6 * u.x + k5 * u.y + k7 * u.x * u.y);
  return vec4(value, gradient);
}

// Gradient of one potential component, n(q) + n(2q) / 2: the second octave's gradient is scaled by
// 2 (chain rule) and by its amplitude 1/2.
vec3 potentialGradient(vec3 q, uint field) {
  return valueNoiseWithGradient(q, field).yzw + valueNoiseWithGradient(q * 2.0, field + 3u).yzw;
}

// Curl of the potential at p (in noise-lattice units), the field drifting with `time`.
vec3 curlNoise(vec3 p, float time) {
  vec3 q = p + vec3(0.31, -1.0, 0.17) * time;
  vec3 g0 = potentialGradient(q, 0u);
  vec3 g1 = potentialGradient(q, 1u);
  vec3 g2 = potentialGradient(q, 2u);
  return vec3(g2.y - g1.z, g0.z - g2.x, g1.x - g0.y);
}

#endif
