// Per-draw constants of the passes that draw the scene's meshes.
#ifndef LLL_DRAW_PUSH_GLSL
#define LLL_DRAW_PUSH_GLSL
#include "shared/gpu_types.h"

layout(push_constant) uniform DrawBlock {
  DrawPush draw;
};

#endif
