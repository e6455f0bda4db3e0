#version 460
// The compute rasterizer's first pass (render/compute_raster.h): one invocation per opaque
// triangle of the frame. It transforms the triangle as visibility.vert does, clips it where it
// crosses the near or far plane or leaves the guard band, culls back faces of single-sided
// primitives, and either covers the pixels of a small bounding box itself, with a 64-bit atomic
// max of (depth, id) per pixel, or appends the triangle to the list the per-pixel pass tests.
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_control_flow_attributes : enable
#include "common/frame.glsl"

layout(local_size_x = 64) in;

layout(constant_id = 20) const uint kTriangleBits = 16u;

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
// The first triangle of each opaque record, and the total last.
layout(std430, set = 0, binding = 21) readonly buffer TriangleStartBlock {
  uint triangleStarts[];
};
layout(push_constant) uniform RasterBlock {
  RasterPush raster;
};

#include "common/raster_triangle.glsl"

void main() {
  uint triangle = (gl_WorkGroupID.y * raster.counts.w + gl_WorkGroupID.x) * 64u + gl_LocalInvocationID.x;
  if (triangle >= raster.counts.x) return;
  // The record holding it: the last whose first triangle is not after it.
  uint lo = 0u, hi = raster.counts.y;  // triangleStarts[lo] <= triangle < triangleStarts[hi]
  while (hi - lo > 1u) {
    uint mid = (lo + hi) / 2u;
    if (triangleStarts[mid] <= triangle)
      lo = mid;
    else
      hi = mid;
  }
  uint record = lo;
  uint local = triangle - triangleStarts[record];
  SurfaceRecord r = surfaceRecords[record];
  mat4 model = meshInstances[r.instance].model;
  vec4 c[3];
  [[unroll]] for (int k = 0; k < 3; ++k) {
    uint v = (sceneIndices[r.firstIndex + 3u * local + uint(k)] + r.vertexOffset) * 3u;
    vec4 world = model * vec4(positions[v], positions[v + 1u], positions[v + 2u], 1.0);
    c[k] = frame.viewProj * world;
  }
  uint id = (record << kTriangleBits) | local;
  bool cullBack = record < raster.counts.z;

  ivec2 size = ivec2(frame.viewport.xy);
  clipAndRasterize(c[0], c[1], c[2], id, cullBack, RasterTarget(size, ivec2(0), size));
}
