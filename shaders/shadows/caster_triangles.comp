#version 460
// The sun's shadow casters rasterized in compute (shadows/shadow_raster.h): one invocation per
// opaque caster triangle, drawn into every cascade's cell of the shadow atlas with the visibility
// buffer's rasterizer (common/raster_triangle.glsl): depth only (the key's id is 0).
#extension GL_EXT_control_flow_attributes : enable
#include "common/frame.glsl"
#include "shared/shadow_types.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 26) readonly buffer SunShadowBlock {
  SunShadow sunShadow;
};
layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

// A shadow cascade's large triangles can span thousands of bins: shadows/caster_bins.comp lists
// them, a workgroup per triangle, instead of the thread that found them.
#define RASTER_BINS_LATER
#include "common/raster_triangle.glsl"

void main() {
  uint triangle = (gl_WorkGroupID.y * raster.counts.w + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (triangle >= raster.counts.x) return;
  uint record, local;
  vec4 world[3];
  rasterTriangleWorld(triangle, record, local, world);
  bool cullBack = record < raster.counts.z;
  int resolution = int(sunShadow.atlas.y);
  ivec2 atlasSize = ivec2(round(sunShadow.atlas.y / sunShadow.atlas.zw));
  for (uint c = 0u; c < sunShadow.config.x; ++c) {
    mat4 toCell = sunShadow.cascadeViewProj[c];
    ivec2 origin = ivec2(int(c % kCascadeColumns), int(c / kCascadeColumns)) * resolution;
    clipAndRasterize(toCell * world[0], toCell * world[1], toCell * world[2], 0u, cullBack,
                     RasterTarget(atlasSize, origin, ivec2(resolution)));
  }
}
