#version 460
// Per-particle lighting from every light (forward).
#include "particles/light_particles.glsl"
