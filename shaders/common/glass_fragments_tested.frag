#version 460
// glass-fragments tested against the compute rasterizer's R32F depth (common/glass_fragments.glsl).
#extension GL_EXT_samplerless_texture_functions : require
#define GLASS_TEST_DEPTH
#include "common/glass_fragments.glsl"
