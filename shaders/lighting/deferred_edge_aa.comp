#version 460
// Edge-detect anti-aliasing after the deferred light pass (Infinity took it from Tabula Rasa,
// GPU Gems 3 ch. 19): a pixel on a depth or normal discontinuity of the G-buffer is blended with
// its four neighbours; elsewhere the lit colour passes through unchanged. Without --aa edge it only
// copies the fp32 accumulation into the HDR target.
#extension GL_EXT_samplerless_texture_functions : require
#include "common/finite.glsl"
#include "shared/gpu_types.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {  // see common/frame.glsl
  FrameUniforms frame;
};
layout(set = 0, binding = 5) uniform texture2D depthImage;
layout(set = 0, binding = 6) uniform texture2D accumulation;
layout(set = 0, binding = 7) uniform texture2D gbuffer1;
layout(set = 0, binding = 8, rgba16f) uniform writeonly image2D hdrImage;

// Reverse-Z depth is affine in screen space across a plane, so its second difference is zero on
// any flat surface however grazing; a relative difference above these bounds is a silhouette.
const vec2 kDepthEdge = vec2(0.02, 0.1);
// 1 - cos of the angle between neighbouring normals: ~18 degrees starts an edge, ~41 is a full one.
const vec2 kNormalEdge = vec2(0.05, 0.25);

layout(constant_id = 0) const bool kEdgeAntiAliasing = true;

const ivec2 kNeighbours[4] = ivec2[](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(frame.viewport.xy);
  if (p.x >= size.x || p.y >= size.y) return;
  vec4 center = texelFetch(accumulation, p, 0);
  if (!kEdgeAntiAliasing) {
    imageStore(hdrImage, p, center);
    return;
  }
  float depth = texelFetch(depthImage, p, 0).r;
  vec3 normal = texelFetch(gbuffer1, p, 0).xyz;
  vec3 color = finiteRadiance(center.rgb);  // Inf * (1 - edge) + ... would be NaN where edge is 0
  float depths[4];
  float normalDelta = 0.0;
  vec3 sum = color;
  for (int i = 0; i < 4; ++i) {
    ivec2 q = clamp(p + kNeighbours[i], ivec2(0), size - 1);
    depths[i] = texelFetch(depthImage, q, 0).r;
    // Background (depth 0) has no normal: a surface next to it is a silhouette.
    bool bothSurfaces = depth > 0.0 && depths[i] > 0.0;
    float delta =
        bothSurfaces ? 1.0 - dot(normal, texelFetch(gbuffer1, q, 0).xyz) : float(depth != depths[i]);
    normalDelta = max(normalDelta, delta);
    sum += finiteRadiance(texelFetch(accumulation, q, 0).rgb);
  }
  float secondDifference =
      abs(depths[0] + depths[1] - 2.0 * depth) + abs(depths[2] + depths[3] - 2.0 * depth);
  float nearest = max(depth, max(max(depths[0], depths[1]), max(depths[2], depths[3])));
  float relative = secondDifference / max(nearest, 1e-30);  // all background: no edge
  float edge = max(smoothstep(kDepthEdge.x, kDepthEdge.y, relative),
                   smoothstep(kNormalEdge.x, kNormalEdge.y, normalDelta));
  imageStore(hdrImage, p, vec4(edge > 0.0 ? mix(color, sum / 5.0, edge) : color, center.a));
}
