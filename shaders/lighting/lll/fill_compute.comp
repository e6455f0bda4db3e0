#version 460
#define LLL_FILL_PASS
// The fill with no rasterizer. One workgroup covers 8x8 tiles, one cell of the light bins
// (common/light_bins.glsl), and reads only the lights binned there: the fill costs about what the
// lights cover on screen, not tiles x lights. Its threads first test 64 of them at a time against
// the group's whole volume and gather the survivors in shared memory, then each thread
// tests those against its own tile exactly (sphere to tile-volume distance, shared/lll_types.h).
// Spots and boxes add a conservative shape test (the cone or box against a sphere bounding the part
// of the tile volume within the light's depth range).
// Each thread owns its tile's list, so links need no atomic exchange at the head, and the group
// allocates all its links of a batch with one atomic on the global counter (shared-memory offsets
// within the group) instead of one per link: 16 full-screen lights at 1080p are 518,400 links.
#include "common/light_bins.glsl"
#include "lighting/lll/light_shape.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

shared uint groupFarBits;
shared uint candidateCount;
shared uint candidates[64];
shared uint groupLinks;
shared uint groupBase;

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

  uvec2 binned = binRange(gl_WorkGroupID.y * binHeader.cellsX + gl_WorkGroupID.x);
  uint head = kLinkEnd;
  for (uint base = 0u; base < binned.y; base += 64u) {
    if (gl_LocalInvocationIndex == 0u) {
      candidateCount = 0u;
      groupLinks = 0u;
    }
    barrier();
    if (base + gl_LocalInvocationIndex < binned.y) {
      uint index = binLights[binned.x + base + gl_LocalInvocationIndex];
      GpuLight light = lights[index];
      if (lightTouches(light, toViewDepthSpace(light.positionRange.xyz), groupSlopes, zNear, groupFar))
        candidates[atomicAdd(candidateCount, 1u)] = index;
    }
    barrier();
    uint count = candidateCount;
    // Which candidates touch this tile: one bit each (at most 64).
    uvec2 hits = uvec2(0u);
    for (uint i = 0u; valid && i < count; ++i) {
      GpuLight light = lights[candidates[i]];
      if (lightTouches(light, toViewDepthSpace(light.positionRange.xyz), ownSlopes, zNear, far))
        hits[i >> 5] |= 1u << (i & 31u);
    }
    uint own = bitCount(hits.x) + bitCount(hits.y);
    uint offset = own > 0u ? atomicAdd(groupLinks, own) : 0u;
    barrier();
    if (gl_LocalInvocationIndex == 0u && groupLinks > 0u)
      groupBase = atomicAdd(counters.linksRequested, groupLinks);
    barrier();
    uint link = groupBase + offset;
    for (uint word = 0u; word < 2u; ++word) {
      while (hits[word] != 0u) {
        uint i = word * 32u + uint(findLSB(hits[word]));
        hits[word] &= hits[word] - 1u;
        if (link >= lll.params.x) break;  // past the pool: counted, not written (the CPU grows it)
        GpuLight light = lights[candidates[i]];
        float z = toViewDepthSpace(light.positionRange.xyz).z, halfDepth = depthHalfExtent(light);
        writeLink(link, candidates[i], z - halfDepth, z + halfDepth, head);
        head = link++;
      }
    }
    barrier();
  }
  if (valid) tileHeads[tileIndex] = head;
}
