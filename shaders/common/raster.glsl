// The compute rasterizer's arithmetic (render/compute_raster.h), shared by the per-triangle pass
// and the per-pixel pass so that both cover exactly the same pixels. It follows Vulkan's rules for
// the hardware pass it replaces: vertices snapped to 1/256 pixel (subPixelPrecisionBits = 8), a
// pixel covered when its centre is inside, or on a top or left edge; counter-clockwise front
// faces; depth z/w interpolated linearly in screen space.
#ifndef LLL_RASTER_GLSL
#define LLL_RASTER_GLSL
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

const int kSubPixelBits = 8;
const uint kRasterBinSize = 32u;  // large triangles are listed per 32x32-pixel bin
const int kSubPixel = 1 << kSubPixelBits;

// Where entry k of `bin` sits in the bin buffer (per bin first a count, binsPerRow x bin rows of
// them, then `capacity` entries per bin), for an image `height` pixels high.
uint rasterBinEntry(uint binsPerRow, uint capacity, uint height, uint bin, uint k) {
  uint bins = binsPerRow * ((height + kRasterBinSize - 1u) / kRasterBinSize);
  return bins + bin * capacity + k;
}

// Pixel id and depth in one 64-bit key: the larger key is the nearer surface (reverse-Z), and 0
// is "nothing drawn" (ids are never all ones, so id + 1 does not wrap).
uint64_t rasterKey(float depth, uint id) {
  return (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(id + 1u);
}

// The edge function of a -> b at p, in units of 1/256 pixel squared: positive to the inside of a
// triangle whose signed area (rasterArea2) is positive.
int64_t rasterEdge(ivec2 a, ivec2 b, ivec2 p) {
  return int64_t(b.x - a.x) * int64_t(p.y - a.y) - int64_t(b.y - a.y) * int64_t(p.x - a.x);
}

// Twice the signed area in y-down framebuffer coordinates; Vulkan's front-face area is its
// negation, so with counter-clockwise front faces a positive value is a back face.
int64_t rasterArea2(ivec2 v0, ivec2 v1, ivec2 v2) {
  return rasterEdge(v0, v1, v2);
}

// Whether a -> b is a top edge (horizontal, inside below) or a left edge (inside to its right),
// for a triangle of positive area in y-down coordinates.
bool rasterTopLeft(ivec2 a, ivec2 b) {
  return (b.y == a.y && b.x > a.x) || b.y < a.y;
}

// The centre of pixel (x, y) in 1/256 pixel.
ivec2 rasterCentre(int x, int y) {
  return ivec2(x * kSubPixel + kSubPixel / 2, y * kSubPixel + kSubPixel / 2);
}

// Whether the centre p is covered, and its depth, for a triangle of positive area2.
bool rasterCovers(ivec2 v0, ivec2 v1, ivec2 v2, uint topLeft, int64_t area2, vec3 z, ivec2 p,
                  out float depth) {
  int64_t e0 = rasterEdge(v1, v2, p);
  int64_t e1 = rasterEdge(v2, v0, p);
  int64_t e2 = rasterEdge(v0, v1, p);
  // On an edge (e == 0) only top and left edges cover: subtracting 1 from the others does it.
  bool inside = e0 - int64_t((topLeft & 1u) == 0u ? 1 : 0) >= 0 &&
                e1 - int64_t((topLeft & 2u) == 0u ? 1 : 0) >= 0 &&
                e2 - int64_t((topLeft & 4u) == 0u ? 1 : 0) >= 0;
  float inverse = 1.0 / float(area2);
  depth = (float(e0) * z.x + float(e1) * z.y + float(e2) * z.z) * inverse;
  return inside;
}

uint rasterTopLeftBits(ivec2 v0, ivec2 v1, ivec2 v2) {
  return (rasterTopLeft(v1, v2) ? 1u : 0u) | (rasterTopLeft(v2, v0) ? 2u : 0u) |
         (rasterTopLeft(v0, v1) ? 4u : 0u);
}

#endif
