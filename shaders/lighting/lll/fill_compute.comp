#version 460
#define LLL_FILL_PASS
// The fill with no rasterizer. One workgroup covers 8x8 tiles: its threads first test 64 lights at a
// time against the group's whole volume and gather the survivors in shared memory, then each thread
// tests those against its own tile exactly (sphere to tile-volume distance, shared/lll_types.h) and
// pushes the links. Spots add a conservative cone test (the cone against a sphere bounding the part
// of the tile volume within the light's depth range).
#include "lighting/lll/light_shape.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

shared uint groupFarBits;
shared uint candidateCount;
shared uint candidates[64];

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

bool lightTouches(GpuLight light, vec3 center, vec4 slopes, float zNear, float zFar) {
  float range = light.positionRange.w;
  if (tileVolumeDistanceSquared(center, slopes, zNear, zFar) > range * range) return false;
  return spotMayTouch(light, center, slopes, zNear, zFar);
}

void main() {
  uvec2 tilesSize = frame.counts.zw;
  uvec2 tile = gl_GlobalInvocationID.xy;
  bool valid = tile.x < tilesSize.x && tile.y < tilesSize.y;
  uint tileIndex = tile.y * tilesSize.x + tile.x;
  float zNear = frame.depthParams.x;
  float far = valid ? tileDepth[tileIndex] : 0.0;
  if (gl_LocalInvocationIndex == 0u) groupFarBits = 0u;
  barrier();
  atomicMax(groupFarBits, floatBitsToUint(far));  // non-negative floats order like their bits
  uvec2 groupFirst = gl_WorkGroupID.xy * 8u;
  uvec2 groupLast = min(groupFirst + 7u, tilesSize - 1u);
  vec4 groupSlopes = slopesOfTiles(groupFirst, groupLast);
  vec4 ownSlopes = slopesOfTiles(tile, tile);
  barrier();
  float groupFar = uintBitsToFloat(groupFarBits);

  uint lightCount = frame.counts.x;
  for (uint base = 0u; base < lightCount; base += 64u) {
    if (gl_LocalInvocationIndex == 0u) candidateCount = 0u;
    barrier();
    uint index = base + gl_LocalInvocationIndex;
    if (index < lightCount) {
      GpuLight light = lights[index];
      if (lightTouches(light, toViewDepthSpace(light.positionRange.xyz), groupSlopes, zNear, groupFar))
        candidates[atomicAdd(candidateCount, 1u)] = index;
    }
    barrier();
    uint count = candidateCount;
    for (uint i = 0u; valid && i < count; ++i) {
      GpuLight light = lights[candidates[i]];
      vec3 center = toViewDepthSpace(light.positionRange.xyz);
      if (!lightTouches(light, center, ownSlopes, zNear, far)) continue;
      float range = light.positionRange.w;
      pushLink(tileIndex, candidates[i], center.z - range, center.z + range);
    }
    barrier();
  }
}
