// Particles lit per pixel (--particle-lighting pixel) by the technique's lights, at their own depth.
#define PARTICLE_LIT
#include "particles/scatter_lights.glsl"
#include "particles/draw_fragment.glsl"
