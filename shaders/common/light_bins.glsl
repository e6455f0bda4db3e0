// The coarse light bins (shared/light_bins_types.h): bindings 11 to 13 of a list build's set 0, and
// the cell rectangle a light's bounding sphere covers on screen.
#ifndef LLL_LIGHT_BINS_GLSL
#define LLL_LIGHT_BINS_GLSL
#include "common/frame.glsl"
#include "shared/light_bins_types.h"

#ifdef LLL_BINS_WRITE
#define LLL_BINS_ACCESS
#else
#define LLL_BINS_ACCESS readonly
#endif

layout(std430, set = 0, binding = 11) LLL_BINS_ACCESS buffer BinHeaderBlock {
  LightBinHeader binHeader;
};
// Written by the tile-depth passes (farBits, LLL_BINS_FAR_WRITE) and the bins' own passes, read
// by the list builds.
#if defined(LLL_BINS_WRITE) || defined(LLL_BINS_FAR_WRITE)
#define LLL_BIN_CELLS_ACCESS
#else
#define LLL_BIN_CELLS_ACCESS readonly
#endif
layout(std430, set = 0, binding = 12) LLL_BIN_CELLS_ACCESS buffer BinCellBlock {
  LightBinCell binCells[];
};
layout(std430, set = 0, binding = 13) LLL_BINS_ACCESS buffer BinLightBlock {
  uint binLights[];
};
#ifdef LLL_BINS_WRITE
// The lights the count pass found too large for one thread (bin_lights.comp).
layout(std430, set = 0, binding = 14) buffer LargeLightBlock {
  uint largeLights[];
};
#endif

// The range of binLights holding cell `cell`'s lights (clamped to the capacity: past it the frame
// is drawn again with more room, see LightBins::afterFrame); every light when the frame has no
// bins (binHeader.unbinned), each entry then the light's index.
uvec2 binRange(uint cell) {
  if (binHeader.unbinned != 0u) return uvec2(0u, binHeader.lightCount);
  uint first = min(binCells[cell].first, binHeader.capacity);
  return uvec2(first, min(binCells[cell].count, binHeader.capacity - first));
}

// The light at `entry` of a range binRange returned.
uint binnedLight(uint entry) {
  return binHeader.unbinned != 0u ? entry : binLights[entry];
}

// Pixel x of view-ray slope u (x / z), pixel y of slope v (y / z, y up).
float pixelOfSlopeX(float u) {
  return (u / frame.depthParams.z + 1.0) * 0.5 * frame.viewport.x;
}
float pixelOfSlopeY(float v) {
  return (1.0 - v / frame.depthParams.w) * 0.5 * frame.viewport.y;
}

// The slopes of the two planes through the eye tangent to a circle of `radius` at (coord, z) with
// z > radius > 0: where the sphere's silhouette lies along one screen axis.
vec2 tangentSlopes(float coord, float z, float radius) {
  float t = sqrt(max(coord * coord + z * z - radius * radius, 0.0));
  float d = z * z - radius * radius;
  return vec2(coord * z - radius * t, coord * z + radius * t) / d;
}

// The units (first xy, last zw, inclusive, clamped to 0..last) of `unitPixels` pixels a side that
// the sphere at view-depth-space `center` (z in front of the eye) with `radius` covers on screen;
// false when it is wholly behind the near plane or off screen. A sphere crossing the near plane
// covers the whole screen (conservative).
bool sphereRect(vec3 center, float radius, float unitPixels, uvec2 last, out uvec4 rect) {
  rect = uvec4(0u);
  float zNear = frame.depthParams.x;
  if (center.z + radius < zNear) return false;
  if (center.z - radius <= zNear) {
    rect = uvec4(0u, 0u, last);
    return true;
  }
  vec2 u = tangentSlopes(center.x, center.z, radius);
  vec2 v = tangentSlopes(center.y, center.z, radius);
  // One pixel of margin for rounding; y flips (slope up = pixel down).
  vec4 pixels = vec4(pixelOfSlopeX(u.x) - 1.0, pixelOfSlopeY(v.y) - 1.0, pixelOfSlopeX(u.y) + 1.0,
                     pixelOfSlopeY(v.x) + 1.0);
  if (pixels.z < 0.0 || pixels.w < 0.0 || pixels.x >= frame.viewport.x || pixels.y >= frame.viewport.y)
    return false;
  vec4 c = floor(max(pixels, vec4(0.0)) / unitPixels);
  rect = uvec4(min(uvec2(c.xy), last), min(uvec2(c.zw), last));
  return true;
}

// The bins' cells the sphere covers.
bool sphereCells(vec3 center, float radius, out uvec4 cells) {
  return sphereRect(center, radius, float(binHeader.cellPixels),
                    uvec2(binHeader.cellsX, binHeader.cellsY) - 1u, cells);
}

// The tiles of the 8x8-tile group starting at `groupFirst` that the sphere covers on screen, packed
// as 4 x 8 bits (first x, first y, last x, last y, relative to the group): what a list build's
// threads check before their exact test. Empty (first > last) when it covers none.
uint sphereTilesInGroup(vec3 center, float radius, uvec2 groupFirst) {
  uvec4 r;
  if (!sphereRect(center, radius, float(frame.counts.y), frame.counts.zw - 1u, r)) return 0x00000101u;
  ivec4 rel = ivec4(r) - ivec4(groupFirst, groupFirst);
  if (rel.z < 0 || rel.w < 0 || rel.x > 7 || rel.y > 7) return 0x00000101u;
  uvec4 c = uvec4(clamp(rel, ivec4(0), ivec4(7)));
  return c.x | (c.y << 8) | (c.z << 16) | (c.w << 24);
}

bool groupTileInRect(uint packedRect, uvec2 local) {
  uvec4 r = (uvec4(packedRect) >> uvec4(0u, 8u, 16u, 24u)) & 0xFFu;
  return all(greaterThanEqual(local, r.xy)) && all(lessThanEqual(local, r.zw));
}

#endif
