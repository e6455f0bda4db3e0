#version 460
// Particles whose radiance the vertex shader computed: unlit (ambient and emission), or lit once
// per particle (--particle-lighting vertex).
#include "particles/draw_fragment.glsl"
