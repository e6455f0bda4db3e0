// Structs read by both C++ and GLSL for the techniques that draw lights as volumes ("deferred",
// "prepass"). Written once here; see shared.h for the rules.
#ifndef LLL_DEFERRED_TYPES_H
#define LLL_DEFERRED_TYPES_H
#include "shared/limits.h"

LLL_NAMESPACE_BEGIN

// One light drawn as a bounding volume this frame: the CPU culled it against the view frustum and
// placed a unit shell (sphere or cone, see lighting/light_volumes.h) around it.
struct LightVolume {
  mat4 model;       // unit shell -> world
  vec4 depthRange;  // x nearest, y farthest linear depth the light reaches; zw unused
  uvec4 light;      // x index into the light array; yzw unused
};
LLL_CHECK_SIZE(LightVolume, 96);

LLL_NAMESPACE_END
#endif
