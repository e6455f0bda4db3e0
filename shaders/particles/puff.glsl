// One puff's look at a point of its quad, shared by the raster draw (draw_fragment.glsl) and the
// tiled compute renderer (lit/particles_tiles.comp.glsl) so both make the same image: its density
// (round, noisy, soft at the rim) and, lit per pixel, the light it scatters there.
#ifndef LLL_PARTICLE_PUFF_GLSL
#define LLL_PARTICLE_PUFF_GLSL
#include "particles/random.glsl"
#include "particles/scattering.glsl"

// Two octaves of value noise (smoothstep-interpolated hashed lattice values, the second at twice the
// frequency) over a lattice of kPuffNoisePeriod^2 points that repeats, baked on the CPU at
// kPuffNoiseTexelsPerCell texels per lattice cell (particles/puff_noise.h: puffNoise) and filtered
// bilinearly by the sampler, which wraps: one read a covered pixel. Hashing the four lattice points
// per pixel cost the H200 28% of the composite pass (65,536 vertex-lit particles: 3.74 ms with it,
// 2.68 with constant noise); an octave a read, two reads.
layout(set = 0, binding = 31) uniform sampler2D puffNoise;

float twoOctaveNoise(vec2 p) {
  return textureLod(puffNoise, p * (1.0 / float(kPuffNoisePeriod)), 0.0).r;
}

// Density of the puff at radius^2 r2: falls smoothly to zero at the rim, broken up by the noise so
// overlapping puffs do not read as discs.
float puffDensity(float r2, vec2 pattern) {
  return (1.0 - r2) * (1.0 - r2) * (0.45 + 0.55 * twoOctaveNoise(pattern));
}

// What does not vary across a particle's quad, from its slot and the frame's light at its centre
// (`centreLight`: per-particle lighting, or zero when lit per pixel).
struct PuffLook {
  vec4 albedoOpacity;
  vec3 baseRadiance;  // ambient, emission and `centreLight`, times the albedo
  float radius;       // of the quad (m)
  vec2 patternSeed;   // where the puff's noise pattern starts
};

PuffLook puffLook(Particle p, uint slot, vec3 centreLight) {
  float t = lifeFraction(p);
  PuffLook look;
  vec3 albedo = colorAt(t) * p.attributes.w;
  look.albedoOpacity = vec4(albedo, opacityAt(t));
  look.baseRadiance = albedo * (frame.ambient.rgb + centreLight + emissionAt(t));
  look.radius = sizeAt(t) * p.attributes.x;
  // Anywhere on the noise's period (32 lattice cells), in 64ths of a cell: exact as a half float,
  // so the compute renderer can stage it as one.
  look.patternSeed = floor(vec2(random01(system.modes.w, slot, 11u), random01(system.modes.w, slot, 12u)) *
                           float(kPuffNoisePeriod * 64u)) /
                     64.0;
  return look;
}

// Soft particles: the puff fades out over the preset's softness (m) in front of the scene.
float softFade(float sceneViewDepth, float viewDepth) {
  return clamp((sceneViewDepth - viewDepth) / system.shading.w, 0.0, 1.0);
}

// The light of the particle at draw order `order` at `offset` on its quad, per unit albedo: its
// atlas's texels interpolated bilinearly, clamped at the outer texels' centres.
vec3 atlasLight(uint order, vec2 offset) {
  const float side = float(kParticleAtlasSide);
  vec2 u = clamp((offset + 1.0) * 0.5 * side - 0.5, vec2(0.0), vec2(side - 1.0));
  uvec2 i = min(uvec2(u), uvec2(kParticleAtlasSide - 2u));
  vec2 f = u - vec2(i);
  uint base = order * kParticleAtlasSide * kParticleAtlasSide + i.y * kParticleAtlasSide + i.x;
  uvec2 t00 = particleAtlas[base], t10 = particleAtlas[base + 1u];
  uvec2 t01 = particleAtlas[base + kParticleAtlasSide], t11 = particleAtlas[base + kParticleAtlasSide + 1u];
  vec3 c00 = vec3(unpackHalf2x16(t00.x), unpackHalf2x16(t00.y).x);
  vec3 c10 = vec3(unpackHalf2x16(t10.x), unpackHalf2x16(t10.y).x);
  vec3 c01 = vec3(unpackHalf2x16(t01.x), unpackHalf2x16(t01.y).x);
  vec3 c11 = vec3(unpackHalf2x16(t11.x), unpackHalf2x16(t11.y).x);
  return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
}

#ifdef LLL_PARTICLE_SCATTER_LIGHTS_GLSL
// Light scattered towards the eye per unit albedo at `world`, offset `offset` (radius 1) on the
// quad, with the normal of a sphere under it; `pixel` and `viewDepth` pick the lighting
// interface's lights.
vec3 puffLight(vec3 world, vec2 offset, float r2, uvec2 pixel, float viewDepth) {
  vec3 normal = normalize(cameraRight() * offset.x + cameraUp() * offset.y + cameraBack() * sqrt(1.0 - r2));
  vec3 towardEye = normalize(frame.cameraPosition.xyz - world);
  return scatterLights(world, normal, towardEye, pixel, viewDepth);
}
#endif

#endif
