#version 460
// Brute-force shading from the visibility buffer (--surfaces visibility): every pixel's rebuilt
// surface evaluates every light, written as the lit radiance (black where nothing was drawn). The
// workgroup loads the lights into shared memory 64 at a time and every pixel loops over those.
#include "common/visibility_surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D hdr;

const uint kLightsPerChunk = 64u;
shared GpuLight chunkLights[kLightsPerChunk];

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  vec3 color = covered ? ambientAndEmissive(s) : vec3(0.0);
  uint lightCount = frame.counts.x;
  for (uint first = 0u; first < lightCount; first += kLightsPerChunk) {
    uint count = min(kLightsPerChunk, lightCount - first);
    if (gl_LocalInvocationIndex < count) chunkLights[gl_LocalInvocationIndex] = lights[first + gl_LocalInvocationIndex];
    barrier();
    if (covered)
      for (uint i = 0u; i < count; ++i) color += evaluateLight(chunkLights[i], s);
    barrier();
  }
  if (inside) imageStore(hdr, ivec2(pixel), vec4(color, 1.0));
}
