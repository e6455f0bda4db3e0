// Light volumes against tile volumes, as every list build tests them (lll's compute fill, the tiled
// and clustered grids): view-depth space (z in front of the eye, y up), the exact sphere-to-tile
// distance (shared/lll_types.h) and conservative cone and box tests. Needs no list bindings.
#ifndef LLL_LIGHT_TILE_TEST_GLSL
#define LLL_LIGHT_TILE_TEST_GLSL
#include "common/brdf.glsl"
#include "common/frame.glsl"
#include "shared/lll_types.h"

// View-space point with z = distance in front of the eye and y up.
vec3 toViewDepthSpace(vec3 world) {
  vec3 v = (frame.view * vec4(world, 1.0)).xyz;
  return vec3(v.x, v.y, -v.z);
}

vec3 directionToViewDepthSpace(vec3 world) {
  vec3 v = mat3(frame.view) * world;
  return vec3(v.x, v.y, -v.z);
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

// View-ray slopes of the tiles first..last (inclusive) of the frame's grid.
vec4 slopesOfTiles(uvec2 first, uvec2 last) {
  float size = float(frame.counts.y);
  vec2 screen = frame.viewport.xy;
  vec2 lo = vec2(first) * size;
  vec2 hi = min(vec2(last + 1u) * size, screen);
  return tileSlopes(lo.x, hi.x, lo.y, hi.y, screen.x, screen.y, frame.depthParams.z, frame.depthParams.w);
}

// Wronski's cone test against a sphere (conservative: never rejects an intersecting pair).
bool coneMayTouchSphere(vec3 apex, vec3 axis, float cosAngle, float range, vec3 center, float radius) {
  vec3 v = center - apex;
  float lengthSq = dot(v, v);
  float along = dot(v, axis);
  float sinAngle = sqrt(max(1.0 - cosAngle * cosAngle, 0.0));
  float closest = cosAngle * sqrt(max(lengthSq - along * along, 0.0)) - along * sinAngle;
  return !(closest > radius || along > radius + range || along < -radius);
}

bool spotMayTouch(GpuLight light, vec3 center, vec4 slopes, float zNear, float zFar) {
  if (uint(light.directionType.w) != kLightSpot) return true;
  float range = light.positionRange.w;
  float z0 = max(zNear, center.z - range), z1 = min(zFar, center.z + range);
  if (z0 > z1) return false;
  // Bounding sphere of the tile volume between z0 and z1 (its eight corners' box).
  vec3 lo = vec3(min(slopes.x * z0, slopes.x * z1), min(slopes.z * z0, slopes.z * z1), z0);
  vec3 hi = vec3(max(slopes.y * z0, slopes.y * z1), max(slopes.w * z0, slopes.w * z1), z1);
  vec3 axis = directionToViewDepthSpace(light.directionType.xyz);
  return coneMayTouchSphere(center, axis, light.spotParams.x, range, 0.5 * (lo + hi), 0.5 * length(hi - lo));
}

// A box against the sphere bounding the tile volume within the box's depth range: the distance
// from the sphere's centre to the box (conservative for the tile, exact for the sphere).
bool boxMayTouch(GpuLight light, vec3 center, vec4 slopes, float zNear, float zFar) {
  vec3 x, y, z;
  boxAxes(light, x, y, z);
  float halfDepth = boxDepthHalfExtent(x, y, z);
  float z0 = max(zNear, center.z - halfDepth), z1 = min(zFar, center.z + halfDepth);
  if (z0 > z1) return false;
  vec3 lo = vec3(min(slopes.x * z0, slopes.x * z1), min(slopes.z * z0, slopes.z * z1), z0);
  vec3 hi = vec3(max(slopes.y * z0, slopes.y * z1), max(slopes.w * z0, slopes.w * z1), z1);
  vec3 d = 0.5 * (lo + hi) - center;
  float radius = 0.5 * length(hi - lo);
  vec3 outside = max(abs(vec3(dot(d, x) / length(x), dot(d, y) / length(y), dot(d, z) / length(z))) -
                         vec3(length(x), length(y), length(z)),
                     0.0);
  return dot(outside, outside) <= radius * radius;
}

bool lightTouches(GpuLight light, vec3 center, vec4 slopes, float zNear, float zFar) {
  float range = light.positionRange.w;
  if (tileVolumeDistanceSquared(center, slopes, zNear, zFar) > range * range) return false;
  if (isBox(light)) return boxMayTouch(light, center, slopes, zNear, zFar);
  return spotMayTouch(light, center, slopes, zNear, zFar);
}

#endif
