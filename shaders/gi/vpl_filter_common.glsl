// What vpl-filter-rows and vpl-filter (gi/vpl_filter_rows.comp, gi/vpl_filter.comp) read of the
// interleaved shading's images, and the test of whether a neighbour lies on a pixel's surface.
#ifndef LLL_VPL_FILTER_COMMON_GLSL
#define LLL_VPL_FILTER_COMMON_GLSL
#include "gi/vpl_interleave_data.glsl"
#include "shared/gpu_types.h"

// A neighbour lies on a pixel's surface where their normals are within about 37 degrees
// (kNormalCos) and it is within 5% of the pixel's depth of the pixel's tangent plane
// (kPlaneTolerance; 25 degrees and 2% gave 40.66 against 40.76 dB, K = 2 against 1, the atrium's
// VPLs at 640x360 on lavapipe).
const float kNormalCos = 0.8;
const float kPlaneTolerance = 0.05;
// The tests chained through a row (a row's pixels against its centre, the centres against the
// pixel): half the angle (cos 18.43 degrees) and half the distance, so that two steps stay about
// within the single test's bounds.
const float kChainNormalCos = 0.9487;
const float kChainPlaneTolerance = 0.025;

layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {  // see common/frame.glsl
  FrameUniforms frame;
};
// Read by texel fetches, not image loads: on the H200 the gather, 49 samples a pixel at K = 4, took
// 0.585 ms through imageLoad and 0.574 through texelFetch (bench/results/h200-2026-12-04/run5).
layout(set = 0, binding = 38) uniform sampler2D vplIndirect;
layout(set = 0, binding = 39) uniform usampler2D vplSurfaceKey;

// The point of the view-space surface seen through pixel centre `p` at view depth `z`.
vec3 viewPosition(ivec2 p, float z) {
  vec2 ndc = (vec2(p) + 0.5) * frame.viewport.zw * 2.0 - 1.0;
  // Framebuffer y points down (the projection flips it), view-space y up.
  return vec3(ndc.x * frame.depthParams.z, -ndc.y * frame.depthParams.w, -1.0) * z;
}

// The class's specular light over f0 that pixel's key holds.
vec3 specularOfKey(uvec4 key) {
  return vec3(unpackHalf2x16(key.y), unpackHalf2x16(key.z).x);
}

// Whether pixel q (its shading's `sample_` and `key`) is a class sample on the surface of the pixel
// with `normal` and view-space `position`: a surface seen, no pixel that evaluated every class,
// normals within `normalCos`, q within `tolerance` of the pixel's tangent plane.
bool sampleOnSurface(ivec2 q, vec4 sample_, uvec4 key, vec3 normal, vec3 position, float normalCos,
                     float tolerance) {
  if (sample_.w < 0.0 || key.w != 0u) return false;
  if (dot(octahedralDecode(unpackSnorm2x16(key.x)), normal) < normalCos) return false;
  return abs(dot(viewPosition(q, sample_.w) - position, normal)) <= tolerance;
}

#endif
