#version 460
// The compute rasterizer's second pass (render/compute_raster.h): one invocation per pixel. Each
// workgroup walks the large triangles listed in its 32x32-pixel bin (all of them when the bin's
// list overflowed) in batches held in shared memory, skipping those whose bounds miss its 8x8
// tile, keeps the nearest (depth, id) among them and the first pass's key, and writes the
// visibility image and the depth the later passes test against.
#extension GL_EXT_shader_atomic_int64 : require
#include "common/frame.glsl"
#include "common/raster.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, set = 0, binding = 22) readonly buffer KeyBlock {
  uint64_t keys[];
};
layout(std430, set = 0, binding = 23) readonly buffer LargeBlock {
  uint largeCount;
  uint largePad0, largePad1, largePad2;
  RasterTriangle largeTriangles[];
};
layout(set = 0, binding = 20, r32ui) uniform writeonly uimage2D visibilityImage;
layout(std430, set = 0, binding = 24) writeonly buffer DepthBlock {
  float depthOut[];
};
layout(std430, set = 0, binding = 25) readonly buffer BinBlock {
  uint binData[];
};
layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

shared RasterTriangle batch[64];

void main() {
  ivec2 size = ivec2(frame.viewport.xy);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inImage = all(lessThan(pixel, size));
  ivec2 tileLo = ivec2(gl_WorkGroupID.xy) * 8, tileHi = tileLo + 7;
  ivec2 p = rasterCentre(pixel.x, pixel.y);
  uint64_t best = inImage ? keys[uint(pixel.y) * uint(size.x) + uint(pixel.x)] : 0ul;
  uvec2 binXY = gl_WorkGroupID.xy * 8u / kRasterBinSize;
  uint bin = binXY.y * raster.large.z + binXY.x;
  uint listed = binData[bin];
  bool overflow = listed > raster.large.w;
  uint count = overflow ? min(largeCount, raster.large.x) : listed;
  for (uint first = 0u; first < count; first += 64u) {
    uint mine = first + gl_LocalInvocationIndex;
    if (mine < count)
      batch[gl_LocalInvocationIndex] =
          largeTriangles[overflow ? mine
                                  : binData[rasterBinEntry(raster.large.z, raster.large.w, uint(size.y), bin,
                                                           mine)]];
    barrier();
    uint n = min(64u, count - first);
    for (uint i = 0u; i < n; ++i) {
      ivec4 box = batch[i].bounds;
      if (box.x > tileHi.x || box.z < tileLo.x || box.y > tileHi.y || box.w < tileLo.y) continue;
      ivec2 v0 = batch[i].v01.xy, v1 = batch[i].v01.zw, v2 = batch[i].v2.xy;
      float depth;
      if (rasterCovers(v0, v1, v2, uint(batch[i].v2.w), rasterArea2(v0, v1, v2), batch[i].depth.xyz, p,
                       depth)) {
        uint64_t key = rasterKey(depth, uint(batch[i].v2.z));
        best = max(best, key);
      }
    }
    barrier();
  }
  if (!inImage) return;
  uint id = best == 0ul ? kNoSurface : uint(best & 0xFFFFFFFFul) - 1u;
  imageStore(visibilityImage, pixel, uvec4(id));
  depthOut[uint(pixel.y) * uint(size.x) + uint(pixel.x)] =
      best == 0ul ? 0.0 : uintBitsToFloat(uint(best >> 32));
}
