// The tiled and clustered grids' lighting interface (shaders/common/lighting.glsl says what an
// interface provides): the lights of the cluster (tile x depth slice) holding the point, and the
// debug views heatmap (lights in that cluster) and tiles.
#ifndef LLL_LIGHTING_INTERFACE_GLSL
#define LLL_LIGHTING_INTERFACE_GLSL
#include "common/brdf.glsl"
#include "common/debug_colors.glsl"
#include "common/grid_data.glsl"
#include "shared/lll_types.h"

struct LightCursor {
  uint next;
  uint end;
};

LightCursor lightsAt(uvec2 pixel, float viewDepth) {
  uvec2 r = clusterLightRange(pixel, viewDepth);
  return LightCursor(r.x, r.y);
}

bool nextLight(inout LightCursor cursor, out uint light) {
  light = 0u;
  if (cursor.next >= cursor.end) return false;
  light = gridLights[cursor.next++];
  return true;
}

vec3 lightingView(Surface s, uvec2 pixel, float viewDepth, vec3 color, out bool replaced) {
  uint view = grid.params.z;
  replaced = view == kDebugHeatmap;
  if (view == kDebugHeatmap) {
    uvec2 r = clusterLightRange(pixel, viewDepth);
    uint count = r.y - r.x;
    return count == 0u ? vec3(0.0) : heat(float(count) / float(frame.display.y));
  }
  if (view == kDebugTiles) {
    uvec2 inTile = pixel % frame.counts.y;
    if (inTile.x == 0u || inTile.y == 0u) return vec3(1.0, 1.0, 0.0);
  }
  return color;
}

#endif
