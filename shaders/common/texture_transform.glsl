// KHR_texture_transform: where a material's texture `slot` (0 base colour, 1 metallic-roughness,
// 2 normal, 3 emissive, 4 occlusion) is sampled for the mesh's TEXCOORD_0 `uv`, and how its
// derivatives turn with it. GpuMaterial (shared/gpu_types.h) holds the transforms (the identity
// for a texture without one). A fragment shader samples a transformed texture with explicit
// gradients (sampleSlot, below): values loaded from a buffer are not defined in a
// quad's helper invocations, so they must not feed implicit derivatives.
#ifndef LLL_TEXTURE_TRANSFORM_GLSL
#define LLL_TEXTURE_TRANSFORM_GLSL
#include "shared/gpu_types.h"

// Whether material `m` has a texture transform other than the identity (kMaterialTextureTransform).
bool hasTextureTransform(GpuMaterial m) {
  return (m.flags.z & kMaterialTextureTransform) != 0u;
}

mat2 textureTransformLinear(GpuMaterial m, uint slot) {
  return mat2(m.uvMatrix[slot].xy, m.uvMatrix[slot].zw);
}

vec2 textureCoordinates(GpuMaterial m, uint slot, vec2 uv) {
  vec4 offsets = m.uvOffset[slot >> 1];
  return textureTransformLinear(m, slot) * uv + ((slot & 1u) == 0u ? offsets.xy : offsets.zw);
}

// A derivative of uv (per pixel right or down) as one of textureCoordinates(m, slot, uv).
vec2 textureCoordinatesDerivative(GpuMaterial m, uint slot, vec2 duv) {
  return textureTransformLinear(m, slot) * duv;
}

// Texture `slot` of material `m` at the fragment's TEXCOORD_0 `uv`, whose derivatives are dx, dy
// (fragment shaders: common/material.glsl, common/visibility_mask.frag).
// Without a texture transform, the implicit derivatives of uv itself, an input every invocation of
// the quad holds. With one, the transformed coordinates' derivatives are the transform of uv's,
// given explicitly: nothing derived from the material buffer may feed an implicit derivative,
// since a helper invocation's loads are not defined (lavapipe's read 0, and the levels of detail at
// triangle edges came out wrong).
vec4 sampleSlot(sampler2D s, GpuMaterial m, uint slot, vec2 uv, vec2 dx, vec2 dy) {
  if (!hasTextureTransform(m)) return texture(s, uv);
  return textureGrad(s, textureCoordinates(m, slot, uv), textureCoordinatesDerivative(m, slot, dx),
                     textureCoordinatesDerivative(m, slot, dy));
}

#endif
