#version 460
#define GRID_BUILD_PASS
// The tiled and clustered grids' light lists (Harada 2012; Olsson et al. 2012), built from the
// light bins like lll's compute fill: one workgroup per cell of 8x8 tiles, one thread per tile.
// Batches of 64 of the cell's lights are tested against the group's volume and the survivors
// gathered in shared memory; each thread then tests them against its own tile exactly and against
// each depth slice the light's depth range spans.
// Clusters hold contiguous index ranges, so the build is two dispatches of this shader
// (specialization constant 0): grid-count counts each cluster's lights and allocates the group's
// ranges with one atomic; grid-write repeats the same tests and writes the indices. Each dispatch
// makes one sweep over the lights (two sweeps in one dispatch desynchronise on lavapipe).
#include "common/grid_data.glsl"
#include "common/light_bins.glsl"
#include "common/light_tile_test.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(constant_id = 0) const uint kWrite = 0u;

const uint kNoCandidate = 0xFFFFFFFFu;

shared uint groupFarBits;
shared uint candidates[64];
shared uint candidateTiles[64];  // sphereTilesInGroup: which of the group's tiles a candidate may touch
shared uint threadTotals[64];
shared uint groupBase;
// Per thread and slice of its tile: the count (grid-count) or the write cursor and end (grid-write).
shared uint slots[64 * kMaxGridSlices];
shared uint ends[64 * kMaxGridSlices];

void main() {
  uvec2 tilesSize = frame.counts.zw;
  uvec2 tile = gl_GlobalInvocationID.xy;
  bool valid = tile.x < tilesSize.x && tile.y < tilesSize.y;
  uint tileIndex = tile.y * tilesSize.x + tile.x;
  uint me = gl_LocalInvocationIndex;
  uint slices = gridSlices();
  float zNear = frame.depthParams.x;
  vec2 range = valid ? tileRange[tileIndex] : vec2(zNear);
  uint row = me * kMaxGridSlices;
  for (uint s = 0u; s < slices; ++s) {
    uvec2 c = kWrite == 1u && valid ? clusters[tileIndex * slices + s] : uvec2(0u);
    slots[row + s] = c.x;
    ends[row + s] = c.x + c.y;
  }
  if (me == 0u) groupFarBits = 0u;
  barrier();
  atomicMax(groupFarBits, floatBitsToUint(range.y));
  uvec2 groupFirst = gl_WorkGroupID.xy * 8u;
  uvec2 groupLast = min(groupFirst + 7u, tilesSize - 1u);
  vec4 groupSlopes = slopesOfTiles(groupFirst, groupLast);
  vec4 ownSlopes = slopesOfTiles(tile, tile);
  barrier();
  float groupFar = uintBitsToFloat(groupFarBits);
  uvec2 binned = binRange(gl_WorkGroupID.y * binHeader.cellsX + gl_WorkGroupID.x);

  for (uint base = 0u; base < binned.y; base += 64u) {
    uint candidate = kNoCandidate;
    if (base + me < binned.y) {
      uint index = binLights[binned.x + base + me];
      GpuLight light = lights[index];
      vec3 center = toViewDepthSpace(light.positionRange.xyz);
      if (lightTouches(light, center, groupSlopes, zNear, groupFar)) {
        candidate = index;
        candidateTiles[me] = sphereTilesInGroup(center, light.positionRange.w, gl_WorkGroupID.xy * 8u);
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
        uint slot = slots[row + s]++;
        // grid-write stays within what grid-count allocated, whatever the float rounding did.
        if (kWrite == 1u && slot < ends[row + s] && slot < grid.params.y) gridLights[slot] = index;
      }
    }
    barrier();
  }

  if (kWrite == 1u) {
    // A cluster that got fewer lights than counted keeps only the ones written.
    for (uint s = 0u; valid && s < slices; ++s) {
      uint written = min(slots[row + s], ends[row + s]);
      uvec2 c = clusters[tileIndex * slices + s];
      if (written != ends[row + s]) {
        clusters[tileIndex * slices + s] = uvec2(c.x, written - c.x);
        atomicAdd(gridCounters.mismatches, 1u);
      }
      if (slots[row + s] > ends[row + s]) atomicAdd(gridCounters.mismatches, 1u);
    }
    return;
  }
  // grid-count: this thread's clusters' first entries, the group's in one atomic.
  uint total = 0u;
  for (uint s = 0u; s < slices; ++s) total += slots[row + s];
  threadTotals[me] = total;
  barrier();
  uint offset = 0u;
  for (uint t = 0u; t < me; ++t) offset += threadTotals[t];
  if (me == 63u) groupBase = atomicAdd(gridCounters.requested, offset + total);
  barrier();
  uint first = groupBase + offset;
  for (uint s = 0u; valid && s < slices; ++s) {
    uint count = slots[row + s];
    clusters[tileIndex * slices + s] = uvec2(first, count);
    if (count > 0u) {
      atomicMax(gridCounters.longest, count);
      atomicAdd(gridCounters.clustersWithLights, 1u);
    }
    first += count;
  }
}
