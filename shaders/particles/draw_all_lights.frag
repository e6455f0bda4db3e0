#version 460
// Particles lit per pixel by every light: the forward reference.
#define PARTICLE_SHADING PARTICLE_SHADING_ALL_LIGHTS
#include "particles/draw_fragment.glsl"
