// What the passes that draw lights as volumes share (techniques "deferred" and "prepass"): the
// placed volumes, the first test of every light pixel, and position reconstruction from depth.
#ifndef LLL_LIGHT_VOLUME_GLSL
#define LLL_LIGHT_VOLUME_GLSL
#extension GL_EXT_samplerless_texture_functions : require
#include "common/frame.glsl"
#include "common/gbuffer.glsl"
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

#endif
