#version 460
// The shadow casters' compute rasterizer, between its two passes (shadows/shadow_raster.h): the
// large triangles caster_triangles.comp listed are appended to every 32x32-texel bin they may
// cover a texel centre of, each by a whole workgroup (a triangle of a near cascade can cover the cascade's
// 4,096 bins).
#include "common/frame.glsl"
#include "shared/shadow_types.h"

layout(local_size_x = 64) in;

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
  rasterBinListed(shadowViewHeader.z);
}
