#version 460
// Deferred light pass: one light's volume, additively blended into the accumulation target.
#include "common/brdf.glsl"
#include "lighting/light_volume.glsl"

layout(set = 0, binding = 6) uniform texture2D gbuffer0;
layout(set = 0, binding = 7) uniform texture2D gbuffer1;

layout(location = 0) flat in uint inVolume;
layout(location = 0) out vec4 outColor;

void main() {
  LightVolume volume = volumes[inVolume];
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float linearDepth = litDepth(volume, pixel);
  if (linearDepth < 0.0) discard;
  vec4 g0 = texelFetch(gbuffer0, pixel, 0);
  vec4 g1 = texelFetch(gbuffer1, pixel, 0);
  Surface s = surfaceFromGbuffer(g0, g1, reconstructPosition(gl_FragCoord.xy, linearDepth));
  outColor = vec4(evaluateLight(lights[volume.light.x], s), 0.0);
}
