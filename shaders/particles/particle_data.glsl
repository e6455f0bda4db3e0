// The particle system's bindings (set 0, beside frame.glsl's 0..2 and lll_data.glsl's 3..7) and
// the curves every pass reads. Buffers are read-only unless the pass defines its writer macro:
// vertex shaders must not declare writable storage (vertexPipelineStoresAndAtomics is off).
#ifndef LLL_PARTICLE_DATA_GLSL
#define LLL_PARTICLE_DATA_GLSL
#include "common/frame.glsl"
#include "shared/particle_types.h"

#ifdef PARTICLE_WRITES_STATE
#define PARTICLE_STATE_ACCESS
#else
#define PARTICLE_STATE_ACCESS readonly
#endif
#ifdef PARTICLE_WRITES_ORDER
#define PARTICLE_ORDER_ACCESS
#else
#define PARTICLE_ORDER_ACCESS readonly
#endif
#ifdef PARTICLE_WRITES_RADIANCE
#define PARTICLE_RADIANCE_ACCESS
#else
#define PARTICLE_RADIANCE_ACCESS readonly
#endif

layout(std430, set = 0, binding = 11) readonly buffer ParticleSystemBlock {  // see frame.glsl
  ParticleUniforms system;
};
layout(std430, set = 0, binding = 12) PARTICLE_STATE_ACCESS buffer ParticleStateBlock {
  Particle particles[];
};
// (sort key, slot) pairs; after the sort, the visible particles back to front, then the rest.
layout(std430, set = 0, binding = 13) PARTICLE_ORDER_ACCESS buffer ParticleOrderBlock {
  uvec2 drawOrder[];
};
layout(std430, set = 0, binding = 14) PARTICLE_ORDER_ACCESS buffer ParticleCounterBlock {
  ParticleCounters particleCounters;
};
// Per-particle lighting (--particle-lighting vertex), by position in the draw order.
layout(std430, set = 0, binding = 15) PARTICLE_RADIANCE_ACCESS buffer ParticleRadianceBlock {
  vec4 particleRadiance[];
};

#ifdef PARTICLE_WRITES_ATLAS
#define PARTICLE_ATLAS_ACCESS
#else
#define PARTICLE_ATLAS_ACCESS readonly
#endif
// Per-particle light atlases (--particle-lighting atlas, shared/particle_types.h).
layout(std430, set = 0, binding = 22) PARTICLE_ATLAS_ACCESS buffer ParticleAtlasBlock {
  uvec2 particleAtlas[];
};

bool isAlive(Particle p) {
  return p.positionAge.w >= 0.0 && p.positionAge.w < p.velocityLifetime.w;
}

float lifeFraction(Particle p) {
  return clamp(p.positionAge.w / p.velocityLifetime.w, 0.0, 1.0);
}

// Piecewise-linear curve through `count` evenly spaced keys, packed four to a vec4.
float curveAt(vec4 k0, vec4 k1, uint count, float t) {
  if (count <= 1u) return k0.x;
  float x = t * float(count - 1u);
  uint i = min(uint(x), count - 2u);
  float keys[8] = float[](k0.x, k0.y, k0.z, k0.w, k1.x, k1.y, k1.z, k1.w);
  return mix(keys[i], keys[i + 1u], x - float(i));
}

float sizeAt(float t) {
  return curveAt(system.sizeKeys[0], system.sizeKeys[1], system.keyCounts.x, t);
}
float opacityAt(float t) {
  return curveAt(system.opacityKeys[0], system.opacityKeys[1], system.keyCounts.y, t);
}
float emissionAt(float t) {
  return curveAt(system.emissionKeys[0], system.emissionKeys[1], system.keyCounts.z, t);
}
vec3 colorAt(float t) {
  uint count = system.keyCounts.w;
  if (count <= 1u) return system.colorKeys[0].rgb;
  float x = t * float(count - 1u);
  uint i = min(uint(x), count - 2u);
  return mix(system.colorKeys[i].rgb, system.colorKeys[i + 1u].rgb, x - float(i));
}

// Radius of the particle's quad (m).
float particleRadius(Particle p) {
  return sizeAt(lifeFraction(p)) * p.attributes.x;
}

#endif
