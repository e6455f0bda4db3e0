// One puff's look at a point of its quad, shared by the raster draw (draw_fragment.glsl) and the
// tiled compute renderer (lit/particles_tiles.comp.glsl) so both make the same image: its density
// (round, noisy, soft at the rim) and, lit per pixel, the light it scatters there.
#ifndef LLL_PARTICLE_PUFF_GLSL
#define LLL_PARTICLE_PUFF_GLSL
#include "particles/random.glsl"
#include "particles/scattering.glsl"

// Value noise: smoothstep-interpolated hashed lattice values over a lattice of kPuffNoisePeriod^2
// points that repeats, the values made on the CPU (particles/puff_noise.h), a texel each. Hashing
// per pixel cost the H200 28% of the composite pass (3.74 ms with it, 2.68 with constant noise, at
// 65,536 vertex-lit particles); a baked texture read with the sampler's bilinear filter took 0.58 of
// the composite's 2.46 ms (settled smoke, 1080p: the reads' latency, with few warps resident, in a
// loop whose every step waits on the one before). The compute renderer now keeps the lattice in
// shared memory (PUFF_NOISE_SHARED: loadPuffLattice() before the first barrier); everything else
// reads the texture; both interpolate the same 8-bit values with the same arithmetic.
layout(set = 0, binding = 31) uniform sampler2D puffNoise;

#ifdef PUFF_NOISE_SHARED
// The lattice, four values a word (value i in bits 8 (i % 4) of word i / 4).
shared uint puffLatticeWords[kPuffNoisePeriod * kPuffNoisePeriod / 4u];

// Called by every invocation of the workgroup (`invocations` of them); a barrier must follow.
void loadPuffLattice(uint invocations) {
  for (uint w = gl_LocalInvocationIndex; w < kPuffNoisePeriod * kPuffNoisePeriod / 4u; w += invocations) {
    ivec2 at = ivec2((w * 4u) % kPuffNoisePeriod, (w * 4u) / kPuffNoisePeriod);
    uint word = 0u;
    for (int i = 0; i < 4; ++i)
      word |= uint(round(texelFetch(puffNoise, at + ivec2(i, 0), 0).r * 255.0)) << (8 * i);
    puffLatticeWords[w] = word;
  }
}

float puffLattice(ivec2 point) {
  uint i = uint(point.y & int(kPuffNoisePeriod - 1u)) * kPuffNoisePeriod + uint(point.x & int(kPuffNoisePeriod - 1u));
  return float((puffLatticeWords[i >> 2u] >> ((i & 3u) * 8u)) & 255u) / 255.0;
}
#else
float puffLattice(ivec2 point) {
  return float(uint(round(texelFetch(puffNoise, point & ivec2(kPuffNoisePeriod - 1u), 0).r * 255.0))) / 255.0;
}
#endif

float valueNoise(vec2 p) {
  vec2 cell = floor(p);
  vec2 f = p - cell;
  vec2 u = f * f * (3.0 - 2.0 * f);
  ivec2 c = ivec2(cell);
  return mix(mix(puffLattice(c), puffLattice(c + ivec2(1, 0)), u.x),
             mix(puffLattice(c + ivec2(0, 1)), puffLattice(c + ivec2(1, 1)), u.x), u.y);
}

// Density of the puff at radius^2 r2: falls smoothly to zero at the rim, broken up by two octaves
// of noise so overlapping puffs do not read as discs.
float puffDensity(float r2, vec2 pattern) {
  float noise = 0.65 * valueNoise(pattern) + 0.35 * valueNoise(pattern * 2.3);
  return (1.0 - r2) * (1.0 - r2) * (0.45 + 0.55 * noise);
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
  look.patternSeed = vec2(random01(system.modes.w, slot, 11u), random01(system.modes.w, slot, 12u)) * 64.0;
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
