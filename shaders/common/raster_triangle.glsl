// The compute rasterizer's per-triangle work (render/compute_raster.h), shared by the visibility
// buffer's pass (common/raster_triangles.comp) and the sun's shadow casters
// (shadows/caster_triangles.comp): clip a triangle, cull it, snap it into a target cell, and cover
// a small bounding box with 64-bit atomic max of (depth, id) per pixel or list it for the per-pixel
// pass. The including shader declares the push constants `raster` (RasterPush).
#ifndef LLL_RASTER_TRIANGLE_GLSL
#define LLL_RASTER_TRIANGLE_GLSL
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_control_flow_attributes : enable
#include "common/raster.glsl"

// What the triangles are: records of (primitive, instance) pairs, each a run of triangles.
layout(std430, set = 0, binding = 16) readonly buffer SurfaceRecordBlock {
  SurfaceRecord surfaceRecords[];
};
layout(std430, set = 0, binding = 17) readonly buffer InstanceBlock {
  MeshInstance meshInstances[];
};
layout(std430, set = 0, binding = 18) readonly buffer PositionBlock {
  float positions[];  // xyz per vertex
};
layout(std430, set = 0, binding = 19) readonly buffer IndexBlock {
  uint sceneIndices[];
};
// The first triangle of each record, and the total last.
layout(std430, set = 0, binding = 21) readonly buffer TriangleStartBlock {
  uint triangleStarts[];
};
layout(std430, set = 0, binding = 22) buffer KeyBlock {
  uint64_t keys[];
};
layout(std430, set = 0, binding = 23) buffer LargeBlock {
  uint largeCount;
  uint largePad0, largePad1, largePad2;
  RasterTriangle largeTriangles[];
};
// Per bin: how many large triangles touch it (first, one per bin), then their list slots.
layout(std430, set = 0, binding = 25) buffer BinBlock {
  uint binData[];
};

// Where a triangle is drawn: its cell of the image (the whole image for the visibility buffer, one
// cascade's square of the shadow atlas), in pixels.
struct RasterTarget {
  ivec2 imageSize;
  ivec2 cellOrigin;
  ivec2 cellSize;
};

// Triangle `triangle` of raster.counts.x: its record (the last whose first triangle is not after
// it; raster.counts.y records), its place in the record's run, and its corners in world space.
void rasterTriangleWorld(uint triangle, out uint record, out uint local, out vec4 world[3]) {
  uint lo = 0u, hi = raster.counts.y;  // triangleStarts[lo] <= triangle < triangleStarts[hi]
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (triangleStarts[mid] <= triangle)
      lo = mid;
    else
      hi = mid;
  }
  record = lo;
  local = triangle - triangleStarts[record];
  SurfaceRecord r = surfaceRecords[record];
  mat4 model = meshInstances[r.instance].model;
  [[unroll]] for (int k = 0; k < 3; ++k) {
    uint v = (sceneIndices[r.firstIndex + 3u * local + uint(k)] + r.vertexOffset) * 3u;
    world[k] = model * vec4(positions[v], positions[v + 1u], positions[v + 2u], 1.0);
  }
}

// Where triangle `t` lies against the tile whose first and last pixel centres are `lo` and `hi`:
// 0 outside (one edge has all four corners outside), 2 covering it whole (every corner inside
// every edge, as rasterCovers decides), 1 in part.
uint rasterTileClass(RasterTriangle t, ivec2 lo, ivec2 hi) {
  ivec2 v[3] = ivec2[3](t.v01.xy, t.v01.zw, t.v2.xy);
  uint topLeft = uint(t.v2.w);
  bool whole = true;
  for (int k = 0; k < 3; ++k) {
    ivec2 a = v[(k + 1) % 3], b = v[(k + 2) % 3];
    int64_t bias = int64_t((topLeft & (1u << k)) == 0u ? 1 : 0);
    uint inside = 0u;
    for (int c = 0; c < 4; ++c) {
      ivec2 p = ivec2((c & 1) == 0 ? lo.x : hi.x, (c & 2) == 0 ? lo.y : hi.y);
      if (rasterEdge(a, b, p) - bias >= 0) ++inside;
    }
    if (inside == 0u) return 0u;
    whole = whole && inside == 4u;
  }
  return whole ? 2u : 1u;
}

// Appends large triangle `slot` (`t`) to the lists of the 32x32-pixel bins its bounds touch, this
// invocation taking every `parts`-th bin from `part`: only to those it may cover a
// pixel centre of (rasterTileClass against the bin: a long thin diagonal triangle's bounds touch
// many bins it misses, and every pixel of such a bin would test it again): on the H200 that took the
// sun's resolve from 0.80 to 0.73 ms. Both passes bin a workgroup a triangle, after their triangle
// pass (shadows/caster_bins.comp, common/raster_bins.comp): binned by the thread that found it, one
// atomic per bin in a serial loop, the atrium's floor held the visibility pass for 0.6 ms at 1080p.
void rasterListInBins(uint slot, RasterTriangle t, uint imageHeight, uint part, uint parts) {
  uvec4 bins = uvec4(t.bounds) / kRasterBinSize;
  uint across = bins.z - bins.x + 1u;
  uint count = across * (bins.w - bins.y + 1u);
  for (uint i = part; i < count; i += parts) {
    uvec2 xy = uvec2(bins.x + i % across, bins.y + i / across);
    ivec2 first = ivec2(xy * kRasterBinSize), last = first + int(kRasterBinSize) - 1;
    if (count > 1u && rasterTileClass(t, rasterCentre(first.x, first.y), rasterCentre(last.x, last.y)) == 0u)
      continue;
    uint bin = xy.y * raster.large.z + xy.x;
    uint k = atomicAdd(binData[bin], 1u);
    if (k < raster.large.w)
      binData[rasterBinEntry(raster.large.z, raster.large.w, imageHeight, bin, k)] = slot;
  }
}

// The binning passes' body (common/raster_bins.comp, shadows/caster_bins.comp): every listed large
// triangle binned by a 64-invocation workgroup, the workgroups taking every gl_NumWorkGroups-th.
void rasterBinListed(uint imageHeight) {
  uint listed = min(largeCount, raster.large.x);
  for (uint slot = gl_WorkGroupID.x; slot < listed; slot += gl_NumWorkGroups.x)
    rasterListInBins(slot, largeTriangles[slot], imageHeight, gl_LocalInvocationID.x, 64u);
}

const int kMaxClipped = 9;  // a triangle clipped by six planes

void cover(ivec2 v0, ivec2 v1, ivec2 v2, uint topLeft, int64_t area2, vec3 z, uint id, ivec4 box,
           uint imageWidth) {
  ivec2 lo = min(min(v0, v1), v2), hi = max(max(v0, v1), v2);
  if (all(lessThan(hi - lo, ivec2(4096)))) {
    // Within 16 pixels: relative to its corner every edge function fits 32 bits (< 2^25), and
    // steps from pixel to pixel by a constant.
    ivec2 a = v0 - lo, b = v1 - lo, c = v2 - lo;
    ivec2 p = rasterCentre(box.x, box.y) - lo;
    int e0 = (c.x - b.x) * (p.y - b.y) - (c.y - b.y) * (p.x - b.x) - ((topLeft & 1u) == 0u ? 1 : 0);
    int e1 = (a.x - c.x) * (p.y - c.y) - (a.y - c.y) * (p.x - c.x) - ((topLeft & 2u) == 0u ? 1 : 0);
    int e2 = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) - ((topLeft & 4u) == 0u ? 1 : 0);
    ivec3 stepX = -ivec3(c.y - b.y, a.y - c.y, b.y - a.y) * kSubPixel;
    ivec3 stepY = ivec3(c.x - b.x, a.x - c.x, b.x - a.x) * kSubPixel;
    ivec3 row = ivec3(e0, e1, e2);
    // Depth from the unbiased edge values, as rasterCovers computes it.
    ivec3 bias =
        ivec3((topLeft & 1u) == 0u ? 1 : 0, (topLeft & 2u) == 0u ? 1 : 0, (topLeft & 4u) == 0u ? 1 : 0);
    float inverse = 1.0 / float(area2);
    for (int y = box.y; y <= box.w; ++y, row += stepY) {
      ivec3 e = row;
      for (int x = box.x; x <= box.z; ++x, e += stepX) {
        if (any(lessThan(e, ivec3(0)))) continue;
        float depth = dot(vec3(e + bias), z) * inverse;
        atomicMax(keys[uint(y) * imageWidth + uint(x)], rasterKey(depth, id));
      }
    }
    return;
  }
  for (int y = box.y; y <= box.w; ++y) {
    for (int x = box.x; x <= box.z; ++x) {
      float depth;
      if (rasterCovers(v0, v1, v2, topLeft, area2, z, rasterCentre(x, y), depth))
        atomicMax(keys[uint(y) * imageWidth + uint(x)], rasterKey(depth, id));
    }
  }
}

// One triangle in clip space, every vertex with w > 0 and inside the guard band, drawn into
// `target`'s cell.
void rasterize(vec4 c0, vec4 c1, vec4 c2, uint id, bool cullBack, RasterTarget target) {
  vec2 size = vec2(target.cellSize);
  vec3 n0 = c0.xyz / c0.w, n1 = c1.xyz / c1.w, n2 = c2.xyz / c2.w;
  ivec2 origin = target.cellOrigin * kSubPixel;
  ivec2 v0 = origin + ivec2(floor((n0.xy * 0.5 + 0.5) * size * float(kSubPixel) + 0.5));
  ivec2 v1 = origin + ivec2(floor((n1.xy * 0.5 + 0.5) * size * float(kSubPixel) + 0.5));
  ivec2 v2 = origin + ivec2(floor((n2.xy * 0.5 + 0.5) * size * float(kSubPixel) + 0.5));
  vec3 z = vec3(n0.z, n1.z, n2.z);
  int64_t area2 = rasterArea2(v0, v1, v2);
  if (area2 == 0 || (cullBack && area2 > 0)) return;
  if (area2 < 0) {
    ivec2 t = v1;
    v1 = v2;
    v2 = t;
    z = z.xzy;
    area2 = -area2;
  }
  // Pixels whose centres lie within the snapped bounds, clamped to the cell.
  ivec2 lo = min(min(v0, v1), v2), hi = max(max(v0, v1), v2);
  ivec4 box = ivec4(-((-(lo - kSubPixel / 2)) >> kSubPixelBits), (hi - kSubPixel / 2) >> kSubPixelBits);
  box = ivec4(max(box.xy, target.cellOrigin), min(box.zw, target.cellOrigin + target.cellSize - 1));
  if (box.x > box.z || box.y > box.w) return;
  uint topLeft = rasterTopLeftBits(v0, v1, v2);
  uint pixels = uint(box.z - box.x + 1) * uint(box.w - box.y + 1);
  if (pixels > raster.large.y) {
    uint slot = atomicAdd(largeCount, 1u);
    if (slot < raster.large.x) {
      RasterTriangle t = RasterTriangle(ivec4(v0, v1), ivec4(v2, int(id), int(topLeft)), vec4(z, 0.0), box);
      largeTriangles[slot] = t;
      return;
    }
    // The list is full: cover it here (slowly, but nothing is lost).
  }
  cover(v0, v1, v2, topLeft, area2, z, id, box, uint(target.imageSize.x));
}

// Signed distance to clip plane k (inside when >= 0): near (z <= w), far (z >= 0), then the guard
// band, `guard` times the view in x and y, which keeps snapped coordinates within 22 bits.
float planeDistance(vec4 c, int k, vec2 guard) {
  switch (k) {
    case 0:
      return c.w - c.z;
    case 1:
      return c.z;
    case 2:
      return guard.x * c.w - c.x;
    case 3:
      return guard.x * c.w + c.x;
    case 4:
      return guard.y * c.w - c.y;
    default:
      return guard.y * c.w + c.y;
  }
}

// Triangle c0 c1 c2 in clip space: culled when outside one plane of the view, clipped where it
// crosses the near or far plane or leaves the guard band, then rasterized into `target`'s cell.
void clipAndRasterize(vec4 c0, vec4 c1, vec4 c2, uint id, bool cullBack, RasterTarget target) {
  vec4 c[kMaxClipped];
  c[0] = c0;
  c[1] = c1;
  c[2] = c2;
  // Outside one plane of the view entirely: nothing to draw.
  vec2 guard = 1.0 + 16384.0 / vec2(target.cellSize);
  uint outside = 0x3Fu, clip = 0u;
  [[unroll]] for (int k = 0; k < 3; ++k) {
    uint out_ = 0u;
    if (c[k].w - c[k].z < 0.0) out_ |= 1u;
    if (c[k].z < 0.0) out_ |= 2u;
    if (c[k].x > c[k].w) out_ |= 4u;
    if (c[k].x < -c[k].w) out_ |= 8u;
    if (c[k].y > c[k].w) out_ |= 16u;
    if (c[k].y < -c[k].w) out_ |= 32u;
    outside &= out_;
    for (int p = 0; p < 6; ++p)
      if (planeDistance(c[k], p, guard) < 0.0) clip |= 1u << p;
  }
  if (outside != 0u) return;
  if (clip == 0u) {
    rasterize(c[0], c[1], c[2], id, cullBack, target);
    return;
  }
  // Sutherland-Hodgman against the planes some vertex is outside of. An edge's crossing is
  // computed from its inside end, so two triangles sharing the edge get the same point.
  int count = 3;
  for (int p = 0; p < 6; ++p) {
    if ((clip & (1u << p)) == 0u) continue;
    vec4 kept[kMaxClipped];
    int n = 0;
    for (int i = 0; i < count; ++i) {
      vec4 a = c[i], b = c[(i + 1) % count];
      float da = planeDistance(a, p, guard), db = planeDistance(b, p, guard);
      if (da >= 0.0 && n < kMaxClipped) kept[n++] = a;
      if ((da >= 0.0) != (db >= 0.0) && n < kMaxClipped) {
        kept[n++] = da >= 0.0 ? mix(a, b, da / (da - db)) : mix(b, a, db / (db - da));
      }
    }
    count = n;
    for (int i = 0; i < n; ++i) c[i] = kept[i];
    if (count < 3) return;
  }
  for (int i = 1; i + 1 < count; ++i) rasterize(c[0], c[i], c[i + 1], id, cullBack, target);
}

// rasterCovers for a listed triangle, first ruled out in 32-bit floats where it can be: each edge
// function is the difference of two products of coordinate differences below 2^24 (exact as
// floats), so its float value is within 2^-22 of the products' magnitudes of the exact one, and
// where it is negative by more than that the pixel is outside. Pixels it may cover are decided, and
// their depth interpolated, by the exact 64-bit evaluation: a depth from the float edges changed
// which of two coplanar surfaces won at a few pixels (against the hardware pass on the H200:
// 27 of 255 at one pixel of the atrium; bench/README.md).
bool rasterCoversListed(RasterTriangle t, ivec2 p, out float depth) {
  ivec2 v0 = t.v01.xy, v1 = t.v01.zw, v2 = t.v2.xy;
  vec3 ab = vec3(v2.x - v1.x, v0.x - v2.x, v1.x - v0.x) * vec3(p.y - v1.y, p.y - v2.y, p.y - v0.y);
  vec3 cd = vec3(v2.y - v1.y, v0.y - v2.y, v1.y - v0.y) * vec3(p.x - v1.x, p.x - v2.x, p.x - v0.x);
  depth = 0.0;
  if (any(lessThan(ab - cd, -(abs(ab) + abs(cd)) * (1.0 / 4194304.0)))) return false;
  return rasterCovers(v0, v1, v2, uint(t.v2.w), rasterArea2(v0, v1, v2), t.depth.xyz, p, depth);
}

// The per-pixel pass: the nearest key at `pixel` of an image `size` pixels large, from the first
// pass's key and the large triangles listed in its 32x32-pixel bin (all of them when the bin's list
// overflowed). `tileLo` is the first pixel of the pixel's 8x8 tile (a multiple of 8, so the tile lies
// in one bin): a triangle whose bounds miss the tile is skipped, a test the same for the tile's
// pixels, and the others' edges are evaluated at the pixel. Nothing is shared between invocations:
// the triangles' records are read by every invocation, the same address across a subgroup. (Each
// 8x8 workgroup first placing its bin's triangles against its tile in shared memory, one
// invocation a triangle between barriers, cost 0.06 ms of threel16's 0.10 ms resolve on the H200,
// bench/README.md.) `inside`: whether `pixel` is one to resolve (its key is read).
uint64_t rasterNearest(ivec2 pixel, ivec2 tileLo, bool inside, ivec2 size) {
  if (!inside) return 0ul;
  ivec2 tileHi = tileLo + 7;
  ivec2 p = rasterCentre(pixel.x, pixel.y);
  uint64_t best = keys[uint(pixel.y) * uint(size.x) + uint(pixel.x)];
  uvec2 binXY = uvec2(tileLo) / kRasterBinSize;
  uint bin = binXY.y * raster.large.z + binXY.x;
  uint listed = binData[bin];
  bool overflow = listed > raster.large.w;
  uint count = overflow ? min(largeCount, raster.large.x) : listed;
  uint entries = rasterBinEntry(raster.large.z, raster.large.w, uint(size.y), bin, 0u);
  for (uint i = 0u; i < count; ++i) {
    RasterTriangle t = largeTriangles[overflow ? i : binData[entries + i]];
    ivec4 box = t.bounds;
    if (box.x > tileHi.x || box.z < tileLo.x || box.y > tileHi.y || box.w < tileLo.y) continue;
    float depth;
    if (rasterCoversListed(t, p, depth)) best = max(best, rasterKey(depth, uint(t.v2.z)));
  }
  return best;
}

// The same, for a workgroup that resolves the 8x8 tile of the image at gl_WorkGroupID.
uint64_t rasterNearest(ivec2 pixel, ivec2 size) {
  return rasterNearest(pixel, ivec2(gl_WorkGroupID.xy) * 8, all(lessThan(pixel, size)), size);
}

#endif
