// Light volumes as the fills see them: a light's centre and depth in view space (depth positive in
// front of the eye), and how far a tile's footprint forces its shape to grow.
#ifndef LLL_LIGHT_SHAPE_GLSL
#define LLL_LIGHT_SHAPE_GLSL
#include "common/brdf.glsl"
#include "common/frame.glsl"
#include "common/lll_data.glsl"

// Spots wider than this are filled as spheres: their cone shell would be larger than the sphere's.
const float kMinConeCos = 0.5;  // 60 degrees

// View-space point with z = distance in front of the eye and y up.
vec3 toViewDepthSpace(vec3 world) {
  vec3 v = (frame.view * vec4(world, 1.0)).xyz;
  return vec3(v.x, v.y, -v.z);
}

vec3 directionToViewDepthSpace(vec3 world) {
  vec3 v = mat3(frame.view) * world;
  return vec3(v.x, v.y, -v.z);
}

// How far a light's shape is pushed out so that every pixel of a tile it touches sees it from the
// tile's centre: half a tile's diagonal at the light's far end.
float tileInflation(float centerDepth, float range) {
  return max(centerDepth + range, 0.0) * lll.grid.z;
}

bool usesCone(GpuLight light) {
  return uint(light.directionType.w) == kLightSpot && light.spotParams.x >= kMinConeCos;
}

bool isBox(GpuLight light) {
  return uint(light.directionType.w) == kLightBox;
}

// A box light's axes in view-depth space, each scaled by its half extent.
void boxAxes(GpuLight light, out vec3 x, out vec3 y, out vec3 z) {
  vec3 worldX, worldY, worldZ;
  boxHalfAxes(light, worldX, worldY, worldZ);
  x = directionToViewDepthSpace(worldX);
  y = directionToViewDepthSpace(worldY);
  z = directionToViewDepthSpace(worldZ);
}

// Half a box's extent along the view axis, from its view-space half axes.
float boxDepthHalfExtent(vec3 x, vec3 y, vec3 z) {
  return abs(x.z) + abs(y.z) + abs(z.z);
}

// Half the light's extent along the view axis: a box's projection onto it, else its range.
float depthHalfExtent(GpuLight light) {
  if (!isBox(light)) return light.positionRange.w;
  vec3 x, y, z;
  boxAxes(light, x, y, z);
  return boxDepthHalfExtent(x, y, z);
}

#endif
