#version 460
// Brute-force shading from the visibility buffer (--surfaces visibility): every pixel's rebuilt
// surface evaluates every light, written as the lit radiance (black where nothing was drawn).
#include "common/visibility_surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 13, rgba16f) uniform writeonly image2D hdr;

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  bool inside = pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y);
  Surface s;
  float viewDepth;
  bool covered = rebuildSurface(pixel, inside, s, viewDepth);  // every invocation: it has barriers
  if (!inside) return;
  vec3 color = vec3(0.0);
  if (covered) {
    color = ambientAndEmissive(s);
    uint lightCount = frame.counts.x;
    for (uint i = 0; i < lightCount; ++i) color += evaluateLight(lights[i], s);
  }
  imageStore(hdr, ivec2(pixel), vec4(color, 1.0));
}
