// Light volumes as the raster fills see them: how far a tile's footprint forces a light's shape to
// grow, and which shell a spot gets (the view-space shape tests are common/light_tile_test.glsl).
#ifndef LLL_LIGHT_SHAPE_GLSL
#define LLL_LIGHT_SHAPE_GLSL
#include "common/light_tile_test.glsl"
#include "common/lll_data.glsl"

// Spots wider than this are filled as spheres: their cone shell would be larger than the sphere's.
const float kMinConeCos = 0.5;  // 60 degrees

// How far a light's shape is pushed out so that every pixel of a tile it touches sees it from the
// tile's centre: half a tile's diagonal at the light's far end.
float tileInflation(float centerDepth, float range) {
  return max(centerDepth + range, 0.0) * lll.grid.z;
}

bool usesCone(GpuLight light) {
  return uint(light.directionType.w) == kLightSpot && light.spotParams.x >= kMinConeCos;
}

#endif
