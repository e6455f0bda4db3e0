#version 460
// common/gbuffer_visibility.glsl where the device indexes the texture table with any index
// (Context::nonUniformTextureFeatures): no workgroup loop over the materials.
#define LLL_NONUNIFORM_TEXTURES
#include "common/gbuffer_visibility.glsl"
