#version 460
// Deferred lighting's sun, as Infinity lit it: a pass of its own over the G-buffer, after the light
// volumes, adding the directional lights (the first shadowed through its cascades,
// common/sun_shadow.glsl) into the accumulation. Compute rather than a full-screen quad: on the
// H200 a full-screen fragment pass runs the same arithmetic many times slower.
#extension GL_EXT_samplerless_texture_functions : require
#include "common/gbuffer.glsl"
#include "common/material_surface.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 5) uniform texture2D depthImage;
layout(set = 0, binding = 6) uniform texture2D gbuffer0;
layout(set = 0, binding = 7) uniform texture2D gbuffer1;
layout(set = 0, binding = 8, rgba32f) uniform image2D accumulation;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(vec2(pixel), frame.viewport.xy))) return;
  float depth = texelFetch(depthImage, pixel, 0).r;
  if (depth <= 0.0) return;  // background
  vec3 position = reconstructPosition(vec2(pixel) + 0.5, linearizeDepth(depth));
  Surface s = surfaceFromGbuffer(texelFetch(gbuffer0, pixel, 0), texelFetch(gbuffer1, pixel, 0), position);
  vec3 sun = directionalLight(s, sunVisibleAt(s.position, s.normal));
  imageStore(accumulation, pixel, imageLoad(accumulation, pixel) + vec4(sun, 0.0));
}
