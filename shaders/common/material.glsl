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
  vec2 dx = dFdx(uv), dy = dFdy(uv);
  return m.baseColorFactor.a * sampleSlot(baseColorTexture, m, 0u, uv, dx, dy).a;
}

// Derivatives are taken first, before any branch: they are undefined in control flow that differs
// across a 2x2 quad. The derivative tangent frame follows the normal texture's coordinates
// (KHR_texture_transform turns its u and v with it).
Surface sampleSurface(GpuMaterial m, vec3 position, vec3 normal, vec4 tangent, vec2 uv, bool frontFacing) {
  vec2 dx = dFdx(uv), dy = dFdy(uv);
  SurfaceDerivatives d = SurfaceDerivatives(dFdx(position), dFdy(position), dx, dy);
  MaterialSamples t;
  t.baseColor = sampleSlot(baseColorTexture, m, 0u, uv, dx, dy);
  t.metallicRoughness = sampleSlot(metallicRoughnessTexture, m, 1u, uv, dx, dy);
  t.normal = sampleSlot(normalTexture, m, 2u, uv, dx, dy).xyz;
  t.emissive = sampleSlot(emissiveTexture, m, 3u, uv, dx, dy).rgb;
  t.occlusion = sampleSlot(occlusionTexture, m, 4u, uv, dx, dy).r;
  if (hasTextureTransform(m)) {
    d.duvx = textureCoordinatesDerivative(m, 2u, dx);
    d.duvy = textureCoordinatesDerivative(m, 2u, dy);
  }
  return assembleSurface(m, t, position, normal, tangent, d, frontFacing);
}

#endif
