// shade_visibility_interleaved.comp where the device indexes the texture table with any index
// (Context::nonUniformTextureFeatures): no workgroup loop over the materials.
#define LLL_NONUNIFORM_TEXTURES
#include "lit/shade_visibility_interleaved.comp.glsl"
