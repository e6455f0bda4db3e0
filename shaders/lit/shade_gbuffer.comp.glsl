// Opaque shading from the thin G-buffer (--surfaces gbuffer with compute shading): each
// invocation reads its pixel's surface from the G-buffer and the depth, and adds the lights of the
// technique's lighting interface to the ambient and emission the G-buffer pass left in the HDR
// target.
#include "common/gbuffer.glsl"
#include "common/lighting.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 9) uniform sampler2D depthImage;
layout(set = 0, binding = 11) uniform texture2D gbuffer0;
layout(set = 0, binding = 12) uniform texture2D gbuffer1;
layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= uint(frame.viewport.x) || pixel.y >= uint(frame.viewport.y)) return;
  ivec2 p = ivec2(pixel);
  float depth = texelFetch(depthImage, p, 0).r;
  if (depth <= 0.0) return;  // background: reverse-Z clears to 0, nothing to light
  float linearDepth = linearizeDepth(depth);
  vec3 position = reconstructPosition(vec2(pixel) + 0.5, linearDepth);
  Surface s = surfaceFromGbuffer(texelFetch(gbuffer0, p, 0), texelFetch(gbuffer1, p, 0), position);
  bool replaced;
  vec3 color =
      lightingView(s, pixel, linearDepth, imageLoad(hdr, p).rgb + lightSurface(s, pixel, linearDepth), replaced);
  imageStore(hdr, p, vec4(color, 1.0));
}
