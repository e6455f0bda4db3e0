// Material sampling for mesh passes: textures in set 1 (neutral 1x1 textures where a material has
// none), factors from the material buffer, normal mapping with a screen-space cotangent frame so
// meshes need no tangents.
#ifndef LLL_MATERIAL_GLSL
#define LLL_MATERIAL_GLSL
#include "common/brdf.glsl"
#include "common/draw_push.glsl"
#include "common/frame.glsl"

layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;
layout(set = 1, binding = 1) uniform sampler2D metallicRoughnessTexture;
layout(set = 1, binding = 2) uniform sampler2D normalTexture;
layout(set = 1, binding = 3) uniform sampler2D emissiveTexture;
layout(set = 1, binding = 4) uniform sampler2D occlusionTexture;

vec3 perturbNormal(vec3 n, vec3 position, vec2 uv, vec3 tangentNormal) {
  vec3 dp1 = dFdx(position);
  vec3 dp2 = dFdy(position);
  vec2 duv1 = dFdx(uv);
  vec2 duv2 = dFdy(uv);
  vec3 dp2perp = cross(dp2, n);
  vec3 dp1perp = cross(n, dp1);
  vec3 t = dp2perp * duv1.x + dp1perp * duv2.x;
  vec3 b = dp2perp * duv1.y + dp1perp * duv2.y;
  float scale = max(dot(t, t), dot(b, b));
  if (scale <= 1e-20) return n;  // no UV variation: keep the geometric normal
  float invmax = inversesqrt(scale);
  return normalize(mat3(t * invmax, b * invmax, n) * tangentNormal);
}

float materialAlpha(GpuMaterial m, vec2 uv) {
  return m.baseColorFactor.a * texture(baseColorTexture, uv).a;
}

Surface sampleSurface(GpuMaterial m, vec3 position, vec3 normal, vec2 uv, bool frontFacing) {
  Surface s;
  s.position = position;
  s.view = normalize(frame.cameraPosition.xyz - position);
  vec3 n = normalize(normal);
  if (!frontFacing) n = -n;
  vec3 tangentNormal = texture(normalTexture, uv).xyz * 2.0 - 1.0;
  tangentNormal.xy *= m.params.z;
  s.normal = perturbNormal(n, position, uv, normalize(tangentNormal));
  vec4 base = m.baseColorFactor * texture(baseColorTexture, uv);
  s.baseColor = base.rgb;
  s.alpha = base.a;
  vec4 mr = texture(metallicRoughnessTexture, uv);
  s.roughness = clamp(m.params.y * mr.g, 0.0, 1.0);
  s.metallic = clamp(m.params.x * mr.b, 0.0, 1.0);
  s.occlusion = 1.0 + m.params.w * (texture(occlusionTexture, uv).r - 1.0);
  s.emissive = m.emissive.rgb * texture(emissiveTexture, uv).rgb;
  return s;
}

// What every technique adds besides its lights: emission and a small constant ambient.
vec3 ambientAndEmissive(Surface s) {
  return frame.ambient.rgb * s.baseColor * s.occlusion + s.emissive;
}

#endif
