// The Light Linked List's data, shared by C++ and GLSL: links, per-frame parameters, and the
// exact distance from a light to a tile's volume that the compute fill tests and the CPU checks.
#ifndef LLL_LLL_TYPES_H
#define LLL_LLL_TYPES_H
#include "shared/gpu_types.h"

LLL_NAMESPACE_BEGIN

// Link formats (the shaders' specialization constant kLinkFormat: common/lll_data.glsl).
// Compact, 8 bytes (Bezrati 1.2.2): x = packHalf2x16(min depth, max depth), both rounded outward;
//   y = light index << 24 | next (24 bits, kCompactLinkEnd ends the list).
// Wide, 16 bytes (Bezrati 1.2.1): min depth, max depth (float bits), light index, next.
LLL_CONST(uint, kLinkCompact, 0u);
LLL_CONST(uint, kLinkWide, 1u);

// Debug views (LllUniforms.params.z).
LLL_CONST(uint, kDebugNone, 0u);
LLL_CONST(uint, kDebugHeatmap, 1u);
LLL_CONST(uint, kDebugBounds, 2u);
LLL_CONST(uint, kDebugTiles, 3u);

// Fill parameters written by the CPU once per frame.
struct LllUniforms {
  // x, y: the screen's share of the tile grid (width / (tilesX * tile), height / (tilesY * tile)),
  //   which maps clip space onto whole tiles so edge tiles are never clipped away;
  // z: tangent of half a tile's diagonal angle: how far, per unit of depth, a tile's pixels lie from
  //   its centre ray (shells and rays are inflated by this so a tile is covered anywhere in it);
  // w: unused.
  vec4 grid;
  // x link pool capacity (links), y unused (the link format is a specialization constant), z debug
  // view, w workgroups per cell of the compute fill (each takes a part of the cell's binned lights).
  uvec4 params;
  // x lists per tile: 1, or its depth slices with --lll-slices (shared/depth_slices.h); y lists per
  // slice: 1, or with --vpl-interleave K 1 + K*K, the lights before the VPLs in the first and each
  // class of VPLs in its own (common/lll_data.glsl, render/interleaved_vpls.h); zw unused.
  uvec4 slicing;
};
LLL_CHECK_SIZE(LllUniforms, 48);

// Most depth slices (lists) per tile of --lll-slices.
LLL_CONST(uint, kMaxLllSlices, 32u);

// Most heads per list (LllUniforms.slicing.y): the lights before the VPLs, then one per VPL class
// of --vpl-interleave K (K * K classes).
LLL_CONST(uint, kMaxLllListClasses, 1u + kMaxVplInterleave * kMaxVplInterleave);

// Raster fills: which lights one instanced draw covers.
struct FillPush {
  uvec4 range;  // x first instance of the batch (bounds ids are relative to it), y shape, zw unused
};
LLL_CHECK_SIZE(FillPush, 16);

// Counters the GPU writes and the CPU reads back after the frame.
struct LllCounters {
  uint linksRequested;  // every allocation attempt, also past the pool's end: the size it must have
  uint longestList;     // written by the stats pass
  uint totalListLength;
  uint listsWithLights;  // lists (tiles, or tile slices) with at least one link
};
LLL_CHECK_SIZE(LllCounters, 16);

// Squared distance from point c to a tile's volume: the view-space frustum slice
// { (x, y, z) : zNear <= z <= zFar, u0 <= x / z <= u1, v0 <= y / z <= v1 }, with z the distance in
// front of the eye and tile = (u0, u1, v0, v1) the tile's edges as view-ray slopes.
// The squared distance at depth z is f(z) = dx(z)^2 + dy(z)^2 + (c.z - z)^2, where dx is how far c.x
// lies outside [u0 z, u1 z] (likewise dy). f is convex and, between the depths where c.x = u z or
// c.y = v z, a quadratic; so its minimum is the clamped stationary point of one of those pieces.
LLL_FUNCTION float tileAxisOutside(float slopeLo, float slopeHi, float coord, float z) {
  return max(max(slopeLo * z - coord, coord - slopeHi * z), 0.0f);
}

LLL_FUNCTION float tileVolumeDistanceSquaredAt(vec3 c, vec4 tile, float z) {
  float dx = tileAxisOutside(tile.x, tile.y, c.x, z);
  float dy = tileAxisOutside(tile.z, tile.w, c.y, z);
  return dx * dx + dy * dy + (c.z - z) * (c.z - z);
}

LLL_FUNCTION float tileVolumeDistanceSquared(vec3 c, vec4 tile, float zNear, float zFar) {
  float z[6];
  z[0] = zNear;
  z[1] = zFar;
  uint n = 2u;
  // Breakpoints where c.x = u z or c.y = v z, inside the depth range.
  float slopes[4];
  slopes[0] = tile.x;
  slopes[1] = tile.y;
  slopes[2] = tile.z;
  slopes[3] = tile.w;
  for (uint i = 0u; i < 4u; ++i) {
    float coord = i < 2u ? c.x : c.y;
    if (slopes[i] != 0.0f) {
      float b = coord / slopes[i];
      if (b > zNear && b < zFar) {
        z[n] = b;
        n = n + 1u;
      }
    }
  }
  for (uint i = 1u; i < n; ++i) {  // insertion sort: at most six depths
    float key = z[i];
    uint j = i;
    while (j > 0u && z[j - 1u] > key) {
      z[j] = z[j - 1u];
      j = j - 1u;
    }
    z[j] = key;
  }
  float best = tileVolumeDistanceSquaredAt(c, tile, zNear);
  for (uint i = 0u; i + 1u < n; ++i) {
    float mid = 0.5f * (z[i] + z[i + 1u]);
    // The active terms at the piece's midpoint define its quadratic sum (a z - b)^2.
    float sumAB = c.z;
    float sumAA = 1.0f;
    if (tile.x * mid - c.x > 0.0f) {
      sumAB += tile.x * c.x;
      sumAA += tile.x * tile.x;
    } else if (c.x - tile.y * mid > 0.0f) {
      sumAB += tile.y * c.x;
      sumAA += tile.y * tile.y;
    }
    if (tile.z * mid - c.y > 0.0f) {
      sumAB += tile.z * c.y;
      sumAA += tile.z * tile.z;
    } else if (c.y - tile.w * mid > 0.0f) {
      sumAB += tile.w * c.y;
      sumAA += tile.w * tile.w;
    }
    float stationary = clamp(sumAB / sumAA, z[i], z[i + 1u]);
    best = min(best, tileVolumeDistanceSquaredAt(c, tile, stationary));
  }
  return min(best, tileVolumeDistanceSquaredAt(c, tile, zFar));
}

// A tile's edges as view-ray slopes (u0, u1, v0, v1): x / z and y / z with y up, for the pixels
// [x0, x1) x [y0, y1) of a width x height image whose frustum has the given half-angle tangents.
LLL_FUNCTION vec4 tileSlopes(float x0, float x1, float y0, float y1, float width, float height,
                             float tanHalfX, float tanHalfY) {
  return vec4((x0 / width * 2.0f - 1.0f) * tanHalfX, (x1 / width * 2.0f - 1.0f) * tanHalfX,
              (1.0f - y1 / height * 2.0f) * tanHalfY, (1.0f - y0 / height * 2.0f) * tanHalfY);
}

LLL_NAMESPACE_END
#endif
