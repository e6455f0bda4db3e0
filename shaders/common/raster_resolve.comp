#version 460
// The compute rasterizer's second pass (render/compute_raster.h): one invocation per pixel keeps
// the nearest (depth, id) of the first pass's key and its bin's large triangles
// (common/raster_triangle.glsl), writes the visibility image and the depth twice: as an image
// for the passes that sample it, and as a buffer the D32 depth image is copied from when a pass
// depth-tests (render/compute_raster.h), and resets the key for the next frame.
#include "common/frame.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 20, r32ui) uniform writeonly uimage2D visibilityImage;
layout(std430, set = 0, binding = 24) writeonly buffer DepthBlock {
  float depthOut[];
};
layout(set = 0, binding = 26, r32f) uniform writeonly image2D depthImage;
layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

#include "common/raster_triangle.glsl"

void main() {
  ivec2 size = ivec2(frame.viewport.xy);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  uint64_t best = rasterNearest(pixel, size);
  if (any(greaterThanEqual(pixel, size))) return;
  uint id = best == 0ul ? kNoSurface : uint(best & 0xFFFFFFFFul) - 1u;
  imageStore(visibilityImage, pixel, uvec4(id));
  float depth = best == 0ul ? 0.0 : uintBitsToFloat(uint(best >> 32));
  imageStore(depthImage, pixel, vec4(depth));
  depthOut[uint(pixel.y) * uint(size.x) + uint(pixel.x)] = depth;
  // Reset for the next frame (RasterWorkspace's resolveResetsKeys): every pixel is resolved once a
  // frame, so the keys need no clear of their own.
  keys[uint(pixel.y) * uint(size.x) + uint(pixel.x)] = 0ul;
}
