#version 460
// Shadow casters rasterized in compute (shadows/shadow_raster.h): one invocation per opaque caster
// triangle, drawn into every view's cell of the shadow atlas (the sun's cascades, or the local
// lights' views that it is within reach of) with the visibility buffer's rasterizer
// (common/raster_triangle.glsl): depth only (the key's id is 0).
#extension GL_EXT_control_flow_attributes : enable
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

// A shadow cascade's large triangles can span thousands of bins: shadows/caster_bins.comp lists
// them, a workgroup per triangle, after this pass.
#include "common/raster_triangle.glsl"

void main() {
  uint triangle = (gl_WorkGroupID.y * raster.counts.w + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (triangle >= raster.counts.x) return;
  uint record, local;
  vec4 world[3];
  rasterTriangleWorld(triangle, record, local, world);
  bool cullBack = record < raster.counts.z;
  ivec2 atlasSize = ivec2(shadowViewHeader.yz);
  // The triangle's bounding sphere, for the lights' reach.
  vec3 centre = (world[0].xyz + world[1].xyz + world[2].xyz) * (1.0 / 3.0);
  float radius = sqrt(max(max(dot(world[0].xyz - centre, world[0].xyz - centre),
                              dot(world[1].xyz - centre, world[1].xyz - centre)),
                          dot(world[2].xyz - centre, world[2].xyz - centre)));
  for (uint v = 0u; v < shadowViewHeader.x; ++v) {
    vec4 reach = shadowViews[v].reach;
    if (reach.w > 0.0 && distance(centre, reach.xyz) > reach.w + radius) continue;
    mat4 toCell = shadowViews[v].viewProj;
    uvec4 cell = shadowViews[v].cell;
    clipAndRasterize(toCell * world[0], toCell * world[1], toCell * world[2], 0u, cullBack,
                     RasterTarget(atlasSize, ivec2(cell.xy), ivec2(cell.zz)));
  }
}
