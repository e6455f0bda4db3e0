// Particles lit per pixel (--particle-lighting pixel) by the technique's lights, at their own depth.
#define PARTICLE_LIT
// scatterLights first: draw_fragment.glsl calls it (a blank line keeps clang-format's include sort away).
#include "particles/scatter_lights.glsl"

#include "particles/draw_fragment.glsl"
