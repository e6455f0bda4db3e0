#version 460
// The shadow casters' compute rasterizer (shadows/shadow_raster.h), first: the keys of this frame's
// views' cells cleared, and no others (the triangle pass writes only within the cells; a pass over
// the whole atlas would clear room kept for views this frame does not draw). Workgroup z is the
// view.
#include "common/frame.glsl"
#include "shared/shadow_types.h"

layout(local_size_x = 8, local_size_y = 8) in;

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
  uvec4 cell = shadowViews[gl_WorkGroupID.z].cell;
  uvec2 local = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(local, cell.zz))) return;
  uvec2 texel = cell.xy + local;
  keys[texel.y * shadowViewHeader.y + texel.x] = 0ul;
}
