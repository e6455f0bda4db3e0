// What both lll shading passes (shade.frag on the geometry, shade.comp on the G-buffer) compute for
// one surface: its unlit radiance plus its tile's lights, or the debug view that replaces them.
#ifndef LLL_SHADE_GLSL
#define LLL_SHADE_GLSL
#include "common/debug_colors.glsl"
#include "common/lll_walk.glsl"

// As ThreeL's view: a listed light's colour where it reaches the surface, grey where the list has
// it but the surface is out of its range (the cost of a coarse shape), black with no list entry.
vec3 boundsView(Surface s, uint tileIndex, float depth) {
  vec3 reached = vec3(0.0);
  bool listed = false;
  uint link = tileHeads[tileIndex], steps = 0u, index;
  while (nextListedLight(link, steps, depth, index)) {
    listed = true;
    GpuLight light = lights[index];
    if (any(greaterThan(evaluateLight(light, s), vec3(0.0))))
      reached = max(reached, light.colorIntensity.rgb);
  }
  return any(greaterThan(reached, vec3(0.0))) ? reached : (listed ? vec3(0.25) : vec3(0.0));
}

// Radiance leaving `s`, seen at `pixel` with linear depth `depth`. `unlit` is its ambient and
// emission. Debug views set `opaque` (they replace the surface, glass included).
vec3 shadeSurface(Surface s, uvec2 pixel, float depth, vec3 unlit, out bool opaque) {
  uint tileIndex = tileIndexOf(pixel);
  uint view = lll.params.z;
  opaque = view == kDebugHeatmap || view == kDebugBounds;
  if (view == kDebugHeatmap) {
    uint count = listLength(tileIndex);
    return count == 0u ? vec3(0.0) : heat(float(count) / float(frame.display.y));
  }
  if (view == kDebugBounds) return boundsView(s, tileIndex, depth);
  vec3 color = unlit + shadeFromLightList(s, tileIndex, depth);
  if (view == kDebugTiles) {
    uvec2 inTile = pixel % frame.counts.y;
    if (inTile.x == 0u || inTile.y == 0u) color = vec3(1.0, 1.0, 0.0);
  }
  return color;
}

#endif
