// The thin G-buffer from the visibility buffer (src/render/gbuffer.h), for deferred: each
// invocation rebuilds its pixel's surface as the shading passes do and writes what
// common/gbuffer.frag writes for it on the geometry: ambient and emission into deferred's fp32
// accumulation target (deferred lights the sun in a pass of its own), the surface into the two
// G-buffer targets (zeros where nothing was drawn, as the raster pass's clear leaves them).
#include "common/gbuffer.glsl"
#include "common/visibility_surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba32f) uniform writeonly image2D accumulation;
layout(set = 0, binding = 14, rgba8) uniform writeonly image2D gbuffer0Out;
layout(set = 0, binding = 15, rgba16f) uniform writeonly image2D gbuffer1Out;

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  if (!inside) return;
  ivec2 p = ivec2(pixel);
  imageStore(accumulation, p, covered ? vec4(ambientAndEmission(s), 1.0) : vec4(0.0));
  imageStore(gbuffer0Out, p, covered ? gbuffer0Of(s) : vec4(0.0));
  imageStore(gbuffer1Out, p, covered ? gbuffer1Of(s) : vec4(0.0));
}
