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

// The fragment's texture coordinate sets and their implicit derivatives: call where every
// invocation of the quad runs.
TexCoordSets texCoordSets(vec2 uv0, vec2 uv1) {
  return TexCoordSets(uv0, dFdx(uv0), dFdy(uv0), uv1, dFdx(uv1), dFdy(uv1));
}

// The material's alpha times the vertex colour's (`vertexAlpha`, glTF's COLOR_0).
float materialAlpha(GpuMaterial m, vec2 uv0, vec2 uv1, float vertexAlpha) {
  return m.baseColorFactor.a * vertexAlpha * sampleSlot(baseColorTexture, m, 0u, texCoordSets(uv0, uv1)).a;
}

// Derivatives are taken first, before any branch: they are undefined in control flow that differs
// across a 2x2 quad. The derivative tangent frame follows the normal texture's coordinates
// (its set, and KHR_texture_transform turns its u and v with it). `color` is the vertex colour
// (glTF's COLOR_0, white without one), which multiplies the base colour.
Surface sampleSurface(GpuMaterial m, vec3 position, vec3 normal, vec4 tangent, vec2 uv0, vec2 uv1, vec4 color,
                      bool frontFacing) {
  TexCoordSets c = texCoordSets(uv0, uv1);
  SurfaceDerivatives d = SurfaceDerivatives(dFdx(position), dFdy(position), c.dx0, c.dy0);
  MaterialSamples t;
  t.baseColor = color * sampleSlot(baseColorTexture, m, 0u, c);
  t.metallicRoughness = sampleSlot(metallicRoughnessTexture, m, 1u, c);
  t.normal = sampleSlot(normalTexture, m, 2u, c).xyz;
  t.emissive = sampleSlot(emissiveTexture, m, 3u, c).rgb;
  t.occlusion = sampleSlot(occlusionTexture, m, 4u, c).r;
  if (usesSecondTexCoord(m, 2u)) {
    d.duvx = c.dx1;
    d.duvy = c.dy1;
  }
  if (hasTextureTransform(m)) {
    d.duvx = textureCoordinatesDerivative(m, 2u, d.duvx);
    d.duvy = textureCoordinatesDerivative(m, 2u, d.duvy);
  }
  return assembleSurface(m, t, position, normal, tangent, d, frontFacing);
}

#endif
