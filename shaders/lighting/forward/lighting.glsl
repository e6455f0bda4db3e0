// The forward reference's lighting interface (shaders/common/lighting.glsl says what an interface
// provides): every light reaches every point, in the light array's order.
#ifndef LLL_LIGHTING_INTERFACE_GLSL
#define LLL_LIGHTING_INTERFACE_GLSL
#include "common/brdf.glsl"
#include "common/frame.glsl"

// Lit compute passes may load the lights in chunks instead of calling nextLight.
#define LIGHTING_EVERY_LIGHT

struct LightCursor {
  uint next;
};

LightCursor lightsAt(uvec2 pixel, float viewDepth) {
  return LightCursor(0u);
}

bool nextLight(inout LightCursor cursor, out uint light) {
  light = cursor.next;
  if (cursor.next >= frame.counts.x) return false;
  ++cursor.next;
  return true;
}

vec3 lightingView(Surface s, uvec2 pixel, float viewDepth, vec3 color, out bool replaced) {
  replaced = false;
  return color;
}

#endif
