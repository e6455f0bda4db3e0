#version 460
// glass-fragments tested by the depth attachment (common/glass_fragments.glsl).
#include "common/glass_fragments.glsl"
