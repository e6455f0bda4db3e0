// Counter-based random numbers: a hash of (seed, particle spawn id, which number), never of time
// or of thread order, so a seed gives the same particles on every run (Jarzynski and Olano 2020,
// "Hash Functions for GPU Rendering": pcg3d).
#ifndef LLL_PARTICLE_RANDOM_GLSL
#define LLL_PARTICLE_RANDOM_GLSL

uvec3 pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

// Uniform in [0, 1): 24 bits, exactly representable as a float.
float random01(uint seed, uint id, uint component) {
  return float(pcg3d(uvec3(seed, id, component)).x >> 8) * (1.0 / 16777216.0);
}

#endif
