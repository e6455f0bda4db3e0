#version 460
// Shading with the light linked list in a compute pass (--lll-shade compute): each invocation reads
// its pixel's surface from the thin G-buffer and the prepass depth, walks its tile's list and adds
// the lights to the ambient and emission the G-buffer pass left in the HDR target. With 8x8
// groups and 8-pixel tiles a group walks one list, so its loads are uniform across the group.
#extension GL_EXT_samplerless_texture_functions : require
#include "common/gbuffer.glsl"
#include "lighting/lll/shade.glsl"

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
  bool opaque;
  vec3 color = shadeSurface(s, pixel, linearDepth, imageLoad(hdr, p).rgb, opaque);
  imageStore(hdr, p, vec4(color, 1.0));
}
