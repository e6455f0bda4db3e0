#version 460
#define GRID_BUILD_PASS
// The tiled and clustered grids' light lists (Harada 2012; Olsson et al. 2012), built from the
// light bins like lll's compute fill: workgroups of 8x8 tiles, one thread per tile, several sharing
// a cell's binned lights when there are many (grid.params.w, see LightBins' cellSplitsFor).
// Batches of 64 lights are tested against the group's volume and the survivors gathered in shared
// memory; each thread then tests those under its tile exactly, and against each depth slice the
// light's depth range spans.
// Clusters hold contiguous index ranges, so this shader runs twice (specialization constant 0):
// grid-count adds each cluster's lights to its count, grid_tiles.comp allocates the ranges, and
// grid-write repeats the same tests and appends the indices at the clusters' cursors.
#include "common/grid_data.glsl"
#include "common/light_bins.glsl"
#include "common/light_tile_test.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const uint kWrite = 0u;

const uint kNoCandidate = 0xFFFFFFFFu;

shared uint groupFarBits;
shared uint candidates[64];
shared uint candidateTiles[64];  // sphereTilesInGroup: which of the group's tiles a candidate may touch
// grid-count: per thread and slice of its tile, the lights this part found.
shared uint counts[64 * kMaxGridSlices];

void main() {
  uint splits = max(grid.params.w, 1u);
  uvec2 cell = uvec2(gl_WorkGroupID.x / splits, gl_WorkGroupID.y);
  uint part = gl_WorkGroupID.x % splits;
  uvec2 tilesSize = frame.counts.zw;
  uvec2 tile = cell * 8u + gl_LocalInvocationID.xy;
  bool valid = tile.x < tilesSize.x && tile.y < tilesSize.y;
  uint tileIndex = tile.y * tilesSize.x + tile.x;
  uint me = gl_LocalInvocationIndex;
  uint slices = gridSlices();
  float zNear = frame.depthParams.x;
  vec2 range = valid ? tileRange[tileIndex] : vec2(zNear);
  uint row = me * kMaxGridSlices;
  for (uint s = 0u; s < slices; ++s) counts[row + s] = 0u;
  if (me == 0u) groupFarBits = 0u;
  barrier();
  atomicMax(groupFarBits, floatBitsToUint(range.y));
  uvec2 groupFirst = cell * 8u;
  uvec2 groupLast = min(groupFirst + 7u, tilesSize - 1u);
  vec4 groupSlopes = slopesOfTiles(groupFirst, groupLast);
  vec4 ownSlopes = slopesOfTiles(tile, tile);
  barrier();
  float groupFar = uintBitsToFloat(groupFarBits);
  uvec2 binned = binRange(cell.y * binHeader.cellsX + cell.x);
  uint partBegin = binned.y * part / splits;
  binned = uvec2(binned.x + partBegin, binned.y * (part + 1u) / splits - partBegin);

  for (uint base = 0u; base < binned.y; base += 64u) {
    uint candidate = kNoCandidate;
    if (base + me < binned.y) {
      uint index = binnedLight(binned.x + base + me);
      GpuLight light = lights[index];
      vec3 center = toViewDepthSpace(light.positionRange.xyz);
      if (lightTouches(light, center, groupSlopes, zNear, groupFar)) {
        candidate = index;
        candidateTiles[me] = sphereTilesInGroup(center, light.positionRange.w, groupFirst);
      }
    }
    candidates[me] = candidate;
    barrier();
    for (uint i = 0u; valid && i < 64u; ++i) {
      uint index = candidates[i];
      // Only the tiles under the light's screen bounds run the exact tests.
      if (index == kNoCandidate || !groupTileInRect(candidateTiles[i], gl_LocalInvocationID.xy)) continue;
      GpuLight light = lights[index];
      vec3 center = toViewDepthSpace(light.positionRange.xyz);
      if (!lightTouches(light, center, ownSlopes, zNear, range.y)) continue;
      float halfDepth = depthHalfExtent(light);
      uint s0 = sliceOf(range, max(center.z - halfDepth, zNear));
      uint s1 = sliceOf(range, min(center.z + halfDepth, range.y));
      // The slices' widened bounds overlap: a light just past a boundary may touch the next one.
      s0 = s0 > 0u ? s0 - 1u : 0u;
      s1 = min(s1 + 1u, slices - 1u);
      for (uint s = s0; s <= s1; ++s) {
        vec2 bounds = sliceBounds(range, s);
        if (!lightTouches(light, center, ownSlopes, bounds.x, bounds.y)) continue;
        if (kWrite == 0u) {
          counts[row + s]++;
        } else {
          uint c = tileIndex * slices + s;
          uint slot = atomicAdd(clusterCursors[c], 1u);
          // Within what grid-count counted, whatever the float rounding did (grid-finish checks).
          if (slot < clusters[c].x + clusters[c].y && slot < grid.params.y) gridLights[slot] = index;
        }
      }
    }
    barrier();
  }
  if (kWrite == 0u)
    for (uint s = 0u; valid && s < slices; ++s)
      if (counts[row + s] > 0u) atomicAdd(clusters[tileIndex * slices + s].y, counts[row + s]);
}
