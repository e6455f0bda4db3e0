// Depth slices of a screen tile, shared by C++ and GLSL: lll's sliced lists (--lll-slices) and the
// clustered grid (--cluster-slices). A tile's slices are split = (front, opaque): `front` slices
// split [zNear, nearest opaque surface) exponentially (glass, particles), `opaque` slices split the
// tile's opaque depth range [nearest, farthest] exponentially (Olsson et al. 2012). With no front
// slice the first opaque slice starts at zNear; one slice is the whole tile. The slice of a depth
// never decreases as the depth grows, so a depth interval covers a run of slices.
#ifndef LLL_DEPTH_SLICES_H
#define LLL_DEPTH_SLICES_H
#include "shared/shared.h"

LLL_NAMESPACE_BEGIN

// lll splits a tile's opaque range only where it is deep: one slice per factor 1.25 of depth.
// Thinner slices only copy each light into more of them (a flat wall's range is a few percent).
LLL_CONST(float, kLllOpaqueSliceStep, 1.25f);

// How lll shares `slices` lists among a tile's front and its opaque range (range: nearest,
// farthest linear depth): at most half go to the opaque range, one per kLllOpaqueSliceStep of it.
LLL_FUNCTION uvec2 lllSliceSplit(vec2 range, uint slices) {
  if (slices <= 1u) return uvec2(0u, 1u);
  float ratio = range.y / range.x;
  uint opaque = 1u;
  if (ratio > kLllOpaqueSliceStep)
    opaque = uint(min(ceil(log(ratio) / log(kLllOpaqueSliceStep)), float(max(slices / 2u, 1u))));
  return uvec2(slices - opaque, opaque);
}

// The slice of a tile that holds `depth`.
LLL_FUNCTION uint depthSliceOf(vec2 range, float depth, uvec2 split, float zNear) {
  if (depth < range.x && split.x > 0u) {
    float frontRatio = range.x / zNear;
    if (split.x == 1u || !(frontRatio > 1.0001f)) return 0u;
    float s = float(split.x) * log(max(depth, zNear) / zNear) / log(frontRatio);
    return uint(min(max(s, 0.0f), float(split.x - 1u)));
  }
  float ratio = range.y / range.x;
  if (split.y <= 1u || !(ratio > 1.0001f) || !(depth > range.x)) return split.x;
  float s = float(split.y) * log(depth / range.x) / log(ratio);
  return split.x + uint(min(max(s, 0.0f), float(split.y - 1u)));
}

// The run of slices (first, last) that a depth interval [minDepth, maxDepth] overlaps.
LLL_FUNCTION uvec2 depthSlicesOverlapping(vec2 range, float minDepth, float maxDepth, uvec2 split,
                                          float zNear) {
  return uvec2(depthSliceOf(range, minDepth, split, zNear), depthSliceOf(range, maxDepth, split, zNear));
}

// The depth bounds of slice `slice`.
LLL_FUNCTION vec2 depthSliceBounds(vec2 range, uint slice, uvec2 split, float zNear) {
  if (slice < split.x) {
    float frontRatio = max(range.x / zNear, 1.0f);
    float lo = slice == 0u ? zNear : zNear * pow(frontRatio, float(slice) / float(split.x));
    float hi = slice + 1u == split.x ? range.x : zNear * pow(frontRatio, float(slice + 1u) / float(split.x));
    return vec2(lo, hi);
  }
  uint k = slice - split.x;
  float ratio = max(range.y / range.x, 1.0f);
  float lo = k == 0u ? (split.x == 0u ? zNear : range.x) : range.x * pow(ratio, float(k) / float(split.y));
  float hi = k + 1u == split.y ? range.y : range.x * pow(ratio, float(k + 1u) / float(split.y));
  return vec2(lo, hi);
}

LLL_NAMESPACE_END
#endif
