#version 460
// Particles lit per pixel by their tile's light linked list at their own depth (technique lll).
#define PARTICLE_SHADING PARTICLE_SHADING_LIGHT_LIST
#include "particles/draw_fragment.glsl"
