#version 460
// Particle quads lit once per particle (--particle-lighting vertex): particles-light wrote the
// light each visible particle receives, by position in the draw order.
#define PARTICLE_VERTEX_LIGHTING
#include "particles/draw_vertex.glsl"
