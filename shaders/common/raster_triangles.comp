#version 460
// The compute rasterizer's first pass (render/compute_raster.h): one invocation per opaque
// triangle of the frame. It transforms the triangle as visibility.vert does, clips it where it
// crosses the near or far plane or leaves the guard band, culls back faces of single-sided
// primitives, and either covers the pixels of a small bounding box itself, with a 64-bit atomic
// max of (depth, id) per pixel, or appends the triangle to the list that common/raster_bins.comp
// bins for the per-pixel pass.
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_control_flow_attributes : enable
#include "common/frame.glsl"

layout(local_size_x = 64) in;

layout(constant_id = 20) const uint kTriangleBits = 16u;

layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

#include "common/raster_triangle.glsl"

void main() {
  uint triangle = (gl_WorkGroupID.y * raster.counts.w + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (triangle >= raster.counts.x) return;
  uint record, local;
  vec4 world[3];
  rasterTriangleWorld(triangle, record, local, world);
  vec4 c[3];
  [[unroll]] for (int k = 0; k < 3; ++k) c[k] = frame.viewProj * world[k];
  uint id = (record << kTriangleBits) | local;
  bool cullBack = record < raster.counts.z;

  ivec2 size = ivec2(frame.viewport.xy);
  clipAndRasterize(c[0], c[1], c[2], id, cullBack, RasterTarget(size, ivec2(0), size));
}
