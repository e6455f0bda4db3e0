// Material sampling for mesh passes: the material's textures in set 1 (neutral 1x1 textures where
// it has none), read with the fragment's implicit derivatives.
#ifndef LLL_MATERIAL_GLSL
#define LLL_MATERIAL_GLSL
#include "common/draw_push.glsl"
#include "common/material_surface.glsl"

layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 1) uniform sampler2D metallicRoughnessTexture;
layout(set = 1, binding = 2) uniform sampler2D normalTexture;
layout(set = 1, binding = 3) uniform sampler2D emissiveTexture;
layout(set = 1, binding = 4) uniform sampler2D occlusionTexture;

float materialAlpha(GpuMaterial m, vec2 uv) {
  return m.baseColorFactor.a * texture(baseColorTexture, textureCoordinates(m, 0u, uv)).a;
}

// Derivatives and implicit-LOD samples are taken first, before any branch: both are undefined in
// control flow that differs across a 2x2 quad (and the texture transforms are applied without
// one: common/texture_transform.glsl). The derivative tangent frame follows the normal texture's
// coordinates (KHR_texture_transform turns its u and v with it).
Surface sampleSurface(GpuMaterial m, vec3 position, vec3 normal, vec4 tangent, vec2 uv, bool frontFacing) {
  vec2 normalUv = textureCoordinates(m, 2u, uv);
  SurfaceDerivatives d = SurfaceDerivatives(dFdx(position), dFdy(position), dFdx(normalUv), dFdy(normalUv));
  MaterialSamples t;
  t.baseColor = texture(baseColorTexture, textureCoordinates(m, 0u, uv));
  t.metallicRoughness = texture(metallicRoughnessTexture, textureCoordinates(m, 1u, uv));
  t.normal = texture(normalTexture, normalUv).xyz;
  t.emissive = texture(emissiveTexture, textureCoordinates(m, 3u, uv)).rgb;
  t.occlusion = texture(occlusionTexture, textureCoordinates(m, 4u, uv)).r;
  return assembleSurface(m, t, position, normal, tangent, d, frontFacing);
}

#endif
