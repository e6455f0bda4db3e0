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
  return m.baseColorFactor.a * texture(baseColorTexture, uv).a;
}

// Derivatives and implicit-LOD samples are taken first, before any branch: both are undefined in
// control flow that differs across a 2x2 quad.
Surface sampleSurface(GpuMaterial m, vec3 position, vec3 normal, vec4 tangent, vec2 uv, bool frontFacing) {
  SurfaceDerivatives d = SurfaceDerivatives(dFdx(position), dFdy(position), dFdx(uv), dFdy(uv));
  MaterialSamples t;
  t.baseColor = texture(baseColorTexture, uv);
  t.metallicRoughness = texture(metallicRoughnessTexture, uv);
  t.normal = texture(normalTexture, uv).xyz;
  t.emissive = texture(emissiveTexture, uv).rgb;
  t.occlusion = texture(occlusionTexture, uv).r;
  return assembleSurface(m, t, position, normal, tangent, d, frontFacing);
}

#endif
