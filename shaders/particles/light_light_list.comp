#version 460
// Per-particle lighting from the tile's light linked list (lll).
#define PARTICLE_LIGHT_LIST
#include "particles/light_particles.glsl"
