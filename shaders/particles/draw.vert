#version 460
// Particle quads whose lighting, if any, the fragment shader adds.
#include "particles/draw_vertex.glsl"
