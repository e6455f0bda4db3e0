// What the passes that draw lights as volumes share (techniques "deferred" and "prepass"): the
// placed volumes, the first test of every light pixel, and position reconstruction from depth.
#ifndef LLL_LIGHT_VOLUME_GLSL
#define LLL_LIGHT_VOLUME_GLSL
#extension GL_EXT_samplerless_texture_functions : require
#include "common/frame.glsl"
#include "shared/deferred_types.h"

layout(std430, set = 0, binding = 3) readonly buffer VolumeBlock {
  LightVolume volumes[];
};
layout(set = 0, binding = 5) uniform texture2D depthImage;

// Linear depth of the pixel's visible surface, or a negative value when the pixel must not be lit
// by `volume`: background (cleared to far) or outside the light's depth range. The range test
// comes first, before any G-buffer read, as in Infinity's light shader.
float litDepth(LightVolume volume, ivec2 pixel) {
  float depth = texelFetch(depthImage, pixel, 0).r;
  float linearDepth = linearizeDepth(depth);
  if (depth <= 0.0 || linearDepth < volume.depthRange.x || linearDepth > volume.depthRange.y) return -1.0;
  return linearDepth;
}

// World position of the pixel's surface from its linear depth: the ray through the pixel with unit
// view depth, built from the camera's axes (the rows of the view matrix), scaled by the depth.
// No matrix inverse per pixel.
vec3 reconstructPosition(vec2 fragCoord, float linearDepth) {
  vec2 ndc = fragCoord * frame.viewport.zw * 2.0 - 1.0;
  vec3 right = vec3(frame.view[0][0], frame.view[1][0], frame.view[2][0]);
  vec3 up = vec3(frame.view[0][1], frame.view[1][1], frame.view[2][1]);
  vec3 back = vec3(frame.view[0][2], frame.view[1][2], frame.view[2][2]);
  // Framebuffer y points down (the projection flips it), view-space y up.
  vec3 ray = right * (ndc.x * frame.depthParams.z) - up * (ndc.y * frame.depthParams.w) - back;
  return frame.cameraPosition.xyz + ray * linearDepth;
}

#endif
