// Depth slices of a screen tile, shared by the clustered grid and lll's sliced lists
// (--cluster-slices, --lll-slices). With n slices, slice 0 holds what lies in front of the tile's
// nearest opaque surface (glass, particles) and slices 1 .. n-1 split the tile's opaque depth range
// [range.x, range.y] exponentially (Olsson et al. 2012); one slice is the whole tile. The slice of
// a depth never decreases as the depth grows, so a depth interval covers a run of slices.
#ifndef LLL_DEPTH_SLICES_GLSL
#define LLL_DEPTH_SLICES_GLSL

uint depthSliceOf(vec2 range, float depth, uint slices) {
  if (slices <= 1u || depth < range.x) return 0u;
  uint last = slices - 1u;
  float ratio = range.y / range.x;
  if (last <= 1u || !(ratio > 1.0001)) return 1u;
  float s = float(last) * log(depth / range.x) / log(ratio);
  return 1u + min(uint(max(s, 0.0)), last - 1u);
}

// The depth bounds of slice `slice` (from zNear for slice 0; the last slice ends at the tile's
// farthest surface, where the tile's volume ends).
vec2 depthSliceBounds(vec2 range, uint slice, uint slices, float zNear) {
  if (slices <= 1u) return vec2(zNear, range.y);
  if (slice == 0u) return vec2(zNear, range.x);
  uint last = slices - 1u;
  float ratio = max(range.y / range.x, 1.0);
  float lo = slice == 1u ? range.x : range.x * pow(ratio, float(slice - 1u) / float(last));
  float hi = slice == last ? range.y : range.x * pow(ratio, float(slice) / float(last));
  return vec2(lo, hi);
}

// The run of slices [x, y] that a depth interval [minDepth, maxDepth] overlaps.
uvec2 depthSlicesOverlapping(vec2 range, float minDepth, float maxDepth, uint slices) {
  return uvec2(depthSliceOf(range, minDepth, slices), depthSliceOf(range, maxDepth, slices));
}

#endif
