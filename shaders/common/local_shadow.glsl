// Local lights' shadows (src/shadows/local_shadows.h): how much of a spot or point light reaches a
// point, looked up in the light's view of the local shadow atlas. Every technique's light
// evaluation reads it through common/brdf.glsl's shadowedAttenuation(): the list walks, the forward
// loop, the light volumes, the pre-pass, glass and the particles' scattering alike.
//
// A light record's spotParams.w names its views (point and spot lights only; 0: no shadow this
// frame): v > 0, one view, v - 1 (a spot's cone); v < 0, six views from -v - 1 (a cube: +x, -x, +y,
// -y, +z, -z, for point lights and spots wider than a cube face).
#ifndef LLL_LOCAL_SHADOW_GLSL
#define LLL_LOCAL_SHADOW_GLSL
#include "common/shadow_compare.glsl"
#include "shared/gpu_types.h"
#include "shared/shadow_types.h"

layout(std430, set = 0, binding = 28) readonly buffer LocalShadowBlock {
  LocalShadowView localShadowViews[];
};
// The atlas's depths, compared by common/shadow_compare.glsl, as the sun's.
layout(set = 0, binding = 29) uniform sampler2D localShadowAtlas;

// Whether the renderer shadows any local light this run (--shadows all); false compiles the lookups
// out of a pass specialized for the scene (render/frame.h, lightTypeConstants).
layout(constant_id = 41) const bool kLocalShadows = true;

// The fraction of `light` that reaches `position` (`l` the unit direction towards the light,
// `distance` to it), 1 lit to 0 shadowed. `normal` (unit, or zero for particles) offsets the lookup
// by a texel-sized step; the depth bias grows with the slope tan(theta) of the surface to the light.
float localShadow(GpuLight light, vec3 position, vec3 normal, vec3 l, float distance) {
  float slot = light.spotParams.w;
  if (!kLocalShadows || slot == 0.0 || uint(light.directionType.w) == kLightBox) return 1.0;
  uint view = uint(abs(slot)) - 1u;
  if (slot < 0.0) {
    // The cube face the point lies in: the major axis of its direction from the light (-l).
    vec3 a = abs(l);
    view += a.x >= a.y && a.x >= a.z ? (l.x < 0.0 ? 0u : 1u)
            : a.y >= a.z             ? (l.y < 0.0 ? 2u : 3u)
                                     : (l.z < 0.0 ? 4u : 5u);
  }
  LocalShadowView v = localShadowViews[view];
  float texel = distance * v.params.x;
  bool surface = dot(normal, normal) > 0.0;
  float cosTheta = clamp(dot(normal, l), 0.05, 1.0);
  float tanTheta = sqrt(1.0 - cosTheta * cosTheta) / cosTheta;
  // Off the surface along its normal, and towards the light by the depth error a texel's slope makes.
  vec3 p = position + normal * (texel * v.params.y) +
           l * (surface ? texel * v.params.z * min(tanTheta, 8.0) : texel);
  vec4 clip = v.viewProj * vec4(p, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  // Outside the view (beyond a spot's cone, where it does not light) or nearer than its near plane.
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z >= 1.0) return 1.0;
  // One texel of the atlas in uv (cells are `1 / params.w` texels square), and the cell's bounds a
  // half texel inside it, so that no filter tap reads the next view's cell.
  vec2 atlasTexel = v.cell.zw * v.params.w;
  vec2 lo = v.cell.xy + 0.5 * atlasTexel, hi = v.cell.xy + v.cell.zw - 0.5 * atlasTexel;
  vec2 at = v.cell.xy + uv * v.cell.zw;
  if (v.config.x == kShadowFilterNone) {
    // The texel's centre, inside the cell.
    at = v.cell.xy + (floor(uv / v.params.w) + 0.5) * atlasTexel;
    return shadowCompareTexel(localShadowAtlas, clamp(at, lo, hi), ndc.z);
  }
  float sum = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      sum += shadowCompareLinear(localShadowAtlas, clamp(at + vec2(x, y) * atlasTexel, lo, hi), ndc.z);
  return sum * (1.0 / 9.0);
}

#endif
