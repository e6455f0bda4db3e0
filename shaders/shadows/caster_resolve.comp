#version 460
// The shadow casters' compute rasterizer, per texel of the atlas (shadows/shadow_raster.h): the
// nearest depth of the first pass's key and its bin's large triangles, for the copy into the atlas.
#include "common/frame.glsl"
#include "shared/shadow_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, set = 0, binding = 24) writeonly buffer DepthBlock {
  float depthOut[];
};
// The views to draw (shared/shadow_types.h, ShadowRasterView): a header, then the views.
layout(std430, set = 0, binding = 26) readonly buffer ShadowViewsBlock {
  uvec4 shadowViewHeader;  // x views, y atlas width, z atlas height
  ShadowRasterView shadowViews[];
};
layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

#include "common/raster_triangle.glsl"

void main() {
  ivec2 size = ivec2(shadowViewHeader.yz);
  ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  uint64_t best = rasterNearest(texel, size);
  if (any(greaterThanEqual(texel, size))) return;
  depthOut[uint(texel.y) * uint(size.x) + uint(texel.x)] = uintBitsToFloat(uint(best >> 32));
}
