// KHR_texture_transform: where a material's texture `slot` (0 base colour, 1 metallic-roughness,
// 2 normal, 3 emissive, 4 occlusion) is sampled for the mesh's texture coordinates `uv` (its
// TEXCOORD_0 or TEXCOORD_1: usesSecondTexCoord), and how their derivatives turn with it.
// GpuMaterial (shared/gpu_types.h) holds the transforms (the identity for a texture without one).
// A fragment shader samples a transformed or second-set texture with explicit gradients
// (sampleSlot, below): values loaded from a buffer are not defined in a quad's helper invocations,
// so they must not feed implicit derivatives.
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

// Whether texture `slot` of material `m` reads TEXCOORD_1 rather than TEXCOORD_0.
bool usesSecondTexCoord(GpuMaterial m, uint slot) {
  return (m.flags.z & (kMaterialSecondTexCoord << slot)) != 0u;
}

// A fragment's two sets of texture coordinates (TEXCOORD_0, TEXCOORD_1) and their derivatives,
// taken where every invocation of the quad runs (texCoordSets, common/material.glsl).
struct TexCoordSets {
  vec2 uv0, dx0, dy0;
  vec2 uv1, dx1, dy1;
};

// Texture `slot` of material `m` at the fragment's coordinates `c` (fragment shaders:
// common/material.glsl, common/visibility_mask.frag).
// With TEXCOORD_0 and no texture transform, the implicit derivatives of uv itself, an input every
// invocation of the quad holds. Otherwise the coordinates' derivatives are given explicitly (the
// transform's of the set's): nothing chosen or derived from the material buffer may feed an
// implicit derivative, since a helper invocation's loads are not defined (lavapipe's read 0, and
// the levels of detail at triangle edges came out wrong).
vec4 sampleSlot(sampler2D s, GpuMaterial m, uint slot, TexCoordSets c) {
  bool second = usesSecondTexCoord(m, slot);
  if (!hasTextureTransform(m) && !second) return texture(s, c.uv0);
  vec2 uv = second ? c.uv1 : c.uv0, dx = second ? c.dx1 : c.dx0, dy = second ? c.dy1 : c.dy0;
  return textureGrad(s, textureCoordinates(m, slot, uv), textureCoordinatesDerivative(m, slot, dx),
                     textureCoordinatesDerivative(m, slot, dy));
}

#endif
