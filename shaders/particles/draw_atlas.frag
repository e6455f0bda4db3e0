#version 460
// Particles lit from their light atlases (--particle-lighting atlas), written by particles-light.
#define PARTICLE_ATLAS
#include "particles/draw_fragment.glsl"
