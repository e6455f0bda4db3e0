// The GPU particle system's data, shared by C++ and GLSL (src/particles, shaders/particles).
// Written once here; see shared.h for the rules.
#ifndef LLL_PARTICLE_TYPES_H
#define LLL_PARTICLE_TYPES_H
#include "shared/limits.h"

LLL_NAMESPACE_BEGIN

// Most particles one system holds (the bar). At 48 bytes each the state is 48 MB, within
// lavapipe's 128 MiB storage buffer cap, and the sort's padded pairs are 8 MiB.
LLL_CONST(uint, kMaxParticles, 1000000u);
// Keys of a curve over a particle's life (size, opacity, emission, colour), evenly spaced.
LLL_CONST(uint, kMaxCurveKeys, 8u);
// Fixed simulation step: --frames N advances the simulation N steps of 1 / 60 s, whatever the
// frame rate, so a seed always gives the same state.
LLL_CONST(uint, kParticleStepsPerSecond, 60u);
// Invocations per group of the per-particle passes (simulate, keys, lighting): a multiple of every
// subgroup size we meet (8 on lavapipe, 32 on NVIDIA, 64 on AMD).
LLL_CONST(uint, kParticleGroupSize, 64u);
// Sort key of a slot that is not drawn (dead or outside the view): after every visible particle.
LLL_CONST(uint, kParticleHiddenKey, 0xFFFFFFFFu);

// Emitter shapes (ParticleUniforms.modes.x) and floor modes (modes.y).
LLL_CONST(uint, kEmitterPoint, 0u);
LLL_CONST(uint, kEmitterDisc, 1u);
LLL_CONST(uint, kEmitterSphere, 2u);
LLL_CONST(uint, kFloorNone, 0u);
LLL_CONST(uint, kFloorBounce, 1u);
LLL_CONST(uint, kFloorKill, 2u);

// One particle slot. Alive while 0 <= age < lifetime; a zero-filled slot (lifetime 0) is dead.
struct Particle {
  vec4 positionAge;       // xyz world position (m), w age (s)
  vec4 velocityLifetime;  // xyz velocity (m/s), w lifetime (s)
  vec4 attributes;        // x size scale, y rotation (rad), z spin (rad/s), w brightness scale
};
LLL_CHECK_SIZE(Particle, 48);

// A preset on the GPU (src/particles/presets.h describes each field), written once per system.
struct ParticleUniforms {
  vec4 emitter;          // xyz position (world), w radius (m)
  vec4 direction;        // xyz unit launch direction, w cos(spread half-angle)
  vec4 speedLifetime;    // x min speed, y max speed (m/s), z min lifetime, w max lifetime (s)
  vec4 forces;           // x drag (1/s), y buoyancy (m/s^2 up at birth, 0 at death), z turbulence
                         // strength (m/s^2), w 1 / turbulence feature size (1/m)
  vec4 gravity;          // xyz (m/s^2), w turbulence speed (1/s): how fast the noise field drifts
  vec4 variation;        // x size variation, y brightness variation, z max spin (rad/s), w restitution
  vec4 shading;          // x wrap, y back-light strength, z back-light focus, w softness (m)
  vec4 blend;            // x additive share (0 alpha blending .. 1 additive), y floor height (m), zw unused
  vec4 sizeKeys[2];      // radius over life (m), kMaxCurveKeys evenly spaced keys
  vec4 opacityKeys[2];   // opacity over life
  vec4 emissionKeys[2];  // emitted radiance over life, a multiple of the colour
  vec4 colorKeys[8];     // rgb albedo over life
  uvec4 keyCounts;       // x size, y opacity, z emission, w colour keys
  uvec4 modes;           // x emitter shape, y floor mode, z capacity (slots), w seed
};
LLL_CHECK_SIZE(ParticleUniforms, 8 * 16 + 14 * 16 + 2 * 16);

// Push constants of one simulation step. Spawn ids count every particle the emitter ever made:
// id k goes to slot k % capacity, and k is what the random numbers of its birth are hashed from.
struct ParticleStepPush {
  uvec4 spawn;  // x slot of the step's first spawn, y spawns this step, z first spawn id (low 32
                // bits), w unused
  vec4 time;    // x step length (s), y time at the step's start (s), z seconds between spawns,
                // w time of the first spawn after the step's start (s)
};
LLL_CHECK_SIZE(ParticleStepPush, 32);

// What the GPU counts while sorting and turns into indirect arguments (particles-indirect).
struct ParticleCounters {
  uvec4 draw;      // VkDrawIndirectCommand: 6 vertices per visible particle, 1 instance, 0, 0
  uvec4 dispatch;  // VkDispatchIndirectCommand of the per-particle lighting pass; w visible particles
  uvec4 alive;     // x alive particles, yzw unused
  uvec4 atlas;     // VkDispatchIndirectCommand of atlas lighting (kParticleAtlasGroup particles a group)
};
LLL_CHECK_SIZE(ParticleCounters, 64);

// The tiled compute renderer (--particle-render compute, src/particles/particle_tiles.cpp): the
// screen in square tiles of kParticleTileSize pixels, one workgroup each; a tile's particles are
// put in order front to back in shared memory (consecutive cells holding at most
// kParticleTileSharedSort together are sorted as one run; a longer cell is marked in a bitmap of
// 32 x kParticleTileBitmapWords keys), and blended kParticleTileSize^2 at a time. On the H200 the
// bitmap beat a bitonic sort from 65 keys on (settled smoke at 1080p, every particle pass: 65,536 at
// full resolution 3.93 -> 3.70 ms against sorting up to 1,024); sorted by rank since (three barriers),
// up to 64 or 256 keys a cell made no difference (composite 2.49 / 2.50 ms, bench/README.md
// 2026-12-03 seventh), and joining a tile's small cells into runs of up to 256 took a million's
// composite from 7.82 to 7.68 ms (2026-12-04 fourth).
LLL_CONST(uint, kParticleTileSize, 16u);
LLL_CONST(uint, kParticleTileSharedSort, 256u);
LLL_CONST(uint, kParticleTileBitmapWords, 1024u);
// Slabs a tile's list is cut into: one per kParticlesPerSlab particle slots, a power of two, at
// most kParticleMaxSlabs (ParticleTileHeader).
LLL_CONST(uint, kParticlesPerSlab, 4096u);
LLL_CONST(uint, kParticleMaxSlabs, 64u);
// Cells a workgroup of particles-bin's prefix sum takes (particles/tile_scan.comp).
LLL_CONST(uint, kParticleScanBlock, 1024u);
// Workgroups a tile's slabs are shared out to (ParticleTileHeader.groups): one tile in the middle of
// a plume may hold thousands of particles and one workgroup would hold up the frame blending them.
// Over is associative: each group blends its run of slabs into (colour, transmittance) and
// particles-resolve combines the runs front to back.
LLL_CONST(uint, kParticleMaxGroups, 32u);
// Of those, a tile uses one per kParticlesPerTileGroup of its particles (at least one): a group
// costs every pixel's depth and layer whatever it blends, which a tile of a few sparse particles
// does not repay (dust: 0.23 ms composite with one group, 0.41 with four). The others write
// nothing and mark themselves kTileGroupUnused (tileGroupOpaque), a group that made its whole tile
// opaque kTileGroupOpaque.
LLL_CONST(uint, kParticlesPerTileGroup, 1024u);
LLL_CONST(uint, kTileGroupOpaque, 1u);
LLL_CONST(uint, kTileGroupUnused, 2u);
// A particle pixel is opaque once less than this share of the light behind it gets through: the
// composite stops blending it, particles-resolve stops combining groups there. The error this leaves
// is far below the fp16 target's own rounding of the raster path's blends; 2^-10 is exact as a half.
LLL_CONST(float, kParticleOpaqueTransmittance, 1.0f / 1024.0f);

// --particle-lighting atlas: each visible particle's light, per unit albedo, on a grid of
// kParticleAtlasSide^2 texels over its quad (offsets -1..1 along the camera's right and up),
// sampled bilinearly by every pixel. Texel (i, j) of the particle at draw order k is
// particleAtlas[k * kParticleAtlasSide^2 + j * kParticleAtlasSide + i], rgb as halves.
LLL_CONST(uint, kParticleAtlasSide, 4u);
// Particles a workgroup of atlas lighting takes, an invocation per texel (kMaxParticles /
// kParticleAtlasGroup groups: within the 65,535 a dispatch holds everywhere).
LLL_CONST(uint, kParticleAtlasGroup, 16u);
// The puffs' noise texture (particles/puff.glsl, src/particles/puff_noise.h): two octaves of value
// noise over a lattice of kPuffNoisePeriod^2 points that repeats, kPuffNoiseTexelsPerCell texels
// per cell (the second octave's cells are half as wide: 4 texels).
LLL_CONST(uint, kPuffNoisePeriod, 32u);
LLL_CONST(uint, kPuffNoiseTexelsPerCell, 8u);

// The tiled renderer's header. It works in particle pixels: the frame's with
// --particle-resolution full, 2 x 2 or 4 x 4 of them (`scale`) at half or quarter resolution. Each tile's
// list is cut into `slabs` by draw order (slab s holds the keys k with k * slabs / visible == s, nearest
// first), so a tile whose front slabs make it opaque never sorts or reads the rest. Its cells (LightBinCell,
// one per tile and slab, tile-major) are summed in blocks of kParticleScanBlock (particles/tile_scan.comp).
struct ParticleTileHeader {
  uint requested;  // entries the scatter asked for, also past `capacity`
  uint capacity;   // entries tileEntries holds
  uint cellsX;     // slabs per tile
  uint cellsY;     // tiles (tilesX x tilesY): cellsX x cellsY cells
  uint tilesX;     // tiles across and down the screen, kParticleTileSize pixels a side
  uint tilesY;
  uint longest;     // the most particles one cell held this frame (the composite's atomicMax)
  uint scale;       // full-resolution pixels per particle pixel along each axis (1, 2 or 4)
  uint groups;      // workgroups per tile, each blending its own run of slabs (particleLayers)
  uint layerWidth;  // particle pixels across and down
  uint layerHeight;
  uint stopped;  // groups that stopped because a group in front made their whole tile opaque
  uint unused;   // groups a tile did not need (kParticlesPerTileGroup)
  uint pad0;
  uint pad1;
  uint pad2;
};
LLL_CHECK_SIZE(ParticleTileHeader, 64);

// What the tiled renderer needs of one visible particle, by position in the draw order: written
// once per frame (particles-bin), read by every pixel of every tile it covers. The quad is a disc
// of radius 1 in "offset" space, parallel to the image plane: a pixel centre p (in pixels) is at
// offset (p - disc.xy) * axes (particleAxes in particles/tiles.glsl: disc.w along x, times the
// frame's axis ratio along y), then turned by -rotation for the puff's pattern. The first 32 bytes
// are all that the composite reads of a particle lit at its centre, which it stages for every
// pixel of a tile to read (a pixel's reads of shared memory are the pass's limit).
struct ParticleScreen {
  vec4 disc;         // xy projected centre (particle pixels), z view depth (m), w offset per pixel along x
  uvec4 look;        // half floats: x rotation (cos, sin), y pattern seed (exact: particles/puff.glsl),
                     // z base radiance (r, g), w (b, opacity); base: not from the lights walked per pixel
  vec4 albedo;       // rgb albedo (per-pixel and atlas lighting), w unused
  vec4 worldRadius;  // xyz world centre, w radius (m)
};
LLL_CHECK_SIZE(ParticleScreen, 64);

// One compare-exchange step of the bitonic sort (src/particles/bitonic_sort.h).
struct SortPush {
  uvec4 step;  // x k (size of the sequences being merged), y j (compare distance), z element count, w unused
};
LLL_CHECK_SIZE(SortPush, 16);

LLL_NAMESPACE_END
#endif
