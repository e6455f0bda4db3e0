// No light at all (shaders/common/lighting.glsl says what an interface provides): the glass and
// smoke of a deferred renderer that has no forward pass for them (`--deferred-translucent unlit`,
// the seeds' Figure 1.1), lit by their ambient and emission alone.
#ifndef LLL_LIGHTING_INTERFACE_GLSL
#define LLL_LIGHTING_INTERFACE_GLSL
#include "common/brdf.glsl"
#include "common/frame.glsl"

struct LightCursor {
  uint unused;
};

LightCursor lightsAt(uvec2 pixel, float viewDepth) {
  return LightCursor(0u);
}

bool nextLight(inout LightCursor cursor, out uint light) {
  light = 0u;
  return false;
}

vec3 lightingView(Surface s, uvec2 pixel, float viewDepth, vec3 color, out bool replaced) {
  replaced = false;
  return color;
}

#endif
