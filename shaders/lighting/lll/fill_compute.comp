#version 460
#define LLL_FILL_PASS
// The fill with no rasterizer. One workgroup covers 8x8 tiles, one cell of the light bins
// (common/light_bins.glsl), and reads only the lights binned there: the fill costs about what the
// lights cover on screen, not tiles x lights. Its threads first test 64 of them at a time against
// the group's whole volume and gather the survivors in shared memory (with their view-space sphere
// and depth bounds, computed once for the group rather than once per thread: H200, 1,048,576 lights,
// the fill went from 3.68 to 3.29 ms with one list, 4.06 to 3.53 with two), then each thread
// tests those against its own tile exactly (sphere to tile-volume distance, shared/lll_types.h).
// Spots and boxes add a conservative shape test (the cone or box against a sphere bounding the part
// of the tile volume within the light's depth range).
// Handing the group's (candidate, tile) pairs out evenly to its threads instead, so that no lane
// idles outside a light's screen bounds, was slower (same lights: fill 3.96 ms with one list, and
// the walks 10% slower too, a tile's links no longer lying together in the pool; commit message).
// The group allocates all its links of a batch with one atomic on the global counter (shared-memory
// offsets within the group) instead of one per link: 16 full-screen lights at 1080p are 518,400
// links. With one list per tile or two (the default: in front of the tile's surfaces, over them),
// each split by VPL class with --vpl-interleave (a batch's candidates are placed in class order), a
// thread writes each list's links of a batch one after another and pushes them at the list's head
// as one segment, with one atomic exchange (the cell's parts share the heads), so a list runs down
// consecutive links (H200: every fill and walk measured faster, 5,144 VPLs with K = 2 7.32 -> 6.71 ms
// a frame; bench/README.md, 2026-12-03). With more slices (--lll-slices) a light gets a link in each
// of its tile's slices its depth bounds overlap, each pushed with an atomic exchange of its own.
#include "common/light_bins.glsl"
#include "lighting/lll/light_shape.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

const uint kShapedCandidate = 0x80000000u;  // light indices are below kMaxLights = 2^24

shared uint groupFarBits;
// Candidates per list class (VPL classes with --vpl-interleave; one otherwise), and where each
// class's run of the batch's candidates begins: a batch's candidates are ordered by class.
shared uint classCounts[kMaxLllListClasses];
shared uint classFirst[kMaxLllListClasses + 1u];
const uint kNoSlot = 0xFFFFFFFFu;  // a light of the batch that is no candidate
// A candidate: its light's index, bit 31 set when its shape needs more than the sphere test (spots,
// boxes); its sphere in view-depth space (centre, range) and depth bounds, computed once for the
// group's 64 threads.
shared uint candidates[64];
shared vec4 candidateSpheres[64];
shared vec2 candidateDepths[64];
shared uint candidateTiles[64];  // sphereTilesInGroup: which of the group's tiles a candidate may touch
shared uint groupLinks;
shared uint groupBase;

// Links for the hits `bits` (candidates of this batch) from `link` on, one after another, each one's
// next the one below it, pushed at head `head` as one segment: a single atomic exchange puts the
// newest at the head, and the oldest takes the head it replaced as its next. Past the pool's end
// nothing is written.
void pushSegment(uvec2 bits, uint head, inout uint link) {
  uint count = min(bitCount(bits.x) + bitCount(bits.y), lll.params.x - min(link, lll.params.x));
  if (count == 0u) return;
  uint end = link + count;
  uint next = atomicExchange(tileHeads[head], end - 1u);
  for (uint word = 0u; word < 2u; ++word) {
    for (; bits[word] != 0u && link < end; bits[word] &= bits[word] - 1u) {
      uint i = word * 32u + uint(findLSB(bits[word]));
      vec2 depths = candidateDepths[i];
      writeLink(link, candidates[i] & ~kShapedCandidate, depths.x, depths.y, next);
      next = link++;
    }
  }
}

// Candidates first..end-1 of a batch as bits.
uvec2 candidateBits(uint first, uint end) {
  uvec2 bits;
  for (uint word = 0u; word < 2u; ++word) {
    uint lo = uint(clamp(int(first) - 32 * int(word), 0, 32));
    uint hi = uint(clamp(int(end) - 32 * int(word), 0, 32));
    bits[word] = lo >= hi ? 0u : (hi == 32u ? 0xFFFFFFFFu : (1u << hi) - 1u) & ~((1u << lo) - 1u);
  }
  return bits;
}

void main() {
  // With many lights a cell's binned lights are split among lll.params.w workgroups (one part
  // each), so the few cells that see most of the lights (down a long view) do not hold up the frame.
  uint splits = max(lll.params.w, 1u);
  uvec2 cell = uvec2(gl_WorkGroupID.x / splits, gl_WorkGroupID.y);
  uint part = gl_WorkGroupID.x % splits;
  uvec2 tilesSize = frame.counts.zw;
  uvec2 tile = cell * 8u + gl_LocalInvocationID.xy;
  bool valid = tile.x < tilesSize.x && tile.y < tilesSize.y;
  uint tileIndex = tile.y * tilesSize.x + tile.x;
  float zNear = frame.depthParams.x;
  vec2 range = valid ? tileRange[tileIndex] : vec2(zNear);
  float far = valid ? range.y : 0.0;
  uint slices = listSlices(), classes = listClasses();
  // One list per tile or two (in front of the tile's surfaces, over them), each split by VPL class
  // or not: a thread pushes each list's links of a batch as one segment of consecutive links. More
  // slices: each link pushed at its head with an atomic exchange.
  bool segments = slices <= 2u;
  uvec2 split = lllSliceSplit(range, slices);
  if (gl_LocalInvocationIndex == 0u) groupFarBits = 0u;
  barrier();
  atomicMax(groupFarBits, floatBitsToUint(far));  // non-negative floats order like their bits
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
    if (gl_LocalInvocationIndex == 0u) groupLinks = 0u;
    if (gl_LocalInvocationIndex < classes) classCounts[gl_LocalInvocationIndex] = 0u;
    barrier();
    uint index = 0u, slot = kNoSlot, lightClass = 0u;
    GpuLight light;
    vec3 center;
    if (base + gl_LocalInvocationIndex < binned.y) {
      index = binnedLight(binned.x + base + gl_LocalInvocationIndex);
      light = lights[index];
      center = toViewDepthSpace(light.positionRange.xyz);
      if (lightTouches(light, center, groupSlopes, zNear, groupFar)) {
        lightClass = lightListClass(index);
        slot = atomicAdd(classCounts[lightClass], 1u);
      }
    }
    if (classes > 1u) {  // ordered by class: a thread's hits of one class lie together
      barrier();
      if (gl_LocalInvocationIndex == 0u) {
        uint first = 0u;
        for (uint c = 0u; c < classes; ++c) {
          classFirst[c] = first;
          first += classCounts[c];
        }
        classFirst[classes] = first;
      }
      barrier();
      if (slot != kNoSlot) slot += classFirst[lightClass];
    }
    if (slot != kNoSlot) {
      bool shaped = isBox(light) || uint(light.directionType.w) == kLightSpot;
      candidates[slot] = index | (shaped ? kShapedCandidate : 0u);
      candidateSpheres[slot] = vec4(center, light.positionRange.w);
      float halfDepth = depthHalfExtent(light);
      candidateDepths[slot] = vec2(center.z - halfDepth, center.z + halfDepth);
      candidateTiles[slot] = sphereTilesInGroup(center, light.positionRange.w, groupFirst);
    }
    barrier();
    uint count = classes > 1u ? classFirst[classes] : classCounts[0];
    // Which candidates touch this tile: one bit each (at most 64).
    uvec2 hits = uvec2(0u);
    for (uint i = 0u; valid && i < count; ++i) {
      // Only the tiles under the light's screen bounds run the exact test: a small light is one
      // or two tiles of the 64, so the group's work is about the links it makes.
      if (!groupTileInRect(candidateTiles[i], gl_LocalInvocationID.xy)) continue;
      // lightTouches, with the sphere the group computed.
      vec4 sphere = candidateSpheres[i];
      if (tileVolumeDistanceSquared(sphere.xyz, ownSlopes, zNear, far) > sphere.w * sphere.w) continue;
      uint shaped = candidates[i];
      if ((shaped & kShapedCandidate) != 0u) {
        GpuLight light = lights[shaped & ~kShapedCandidate];
        if (isBox(light) ? !boxMayTouch(light, sphere.xyz, ownSlopes, zNear, far)
                         : !spotMayTouch(light, sphere.xyz, ownSlopes, zNear, far))
          continue;
      }
      hits[i >> 5] |= 1u << (i & 31u);
    }
    uint own = bitCount(hits.x) + bitCount(hits.y);
    // With two lists, which hits go in the front list and which in the opaque one.
    uvec2 frontHits = uvec2(0u), opaqueHits = uvec2(0u);
    for (uint word = 0u; slices > 1u && word < 2u; ++word) {
      own -= bitCount(hits[word]);
      for (uint bits = hits[word]; bits != 0u; bits &= bits - 1u) {
        vec2 depths = candidateDepths[word * 32u + uint(findLSB(bits))];
        uvec2 run = depthSlicesOverlapping(range, depths.x, depths.y, split, zNear);
        own += run.y - run.x + 1u;
        uint bit = bits & (~bits + 1u);
        if (run.x == 0u) frontHits[word] |= bit;
        if (run.y == 1u) opaqueHits[word] |= bit;
      }
    }
    uint offset = own > 0u ? atomicAdd(groupLinks, own) : 0u;
    barrier();
    if (gl_LocalInvocationIndex == 0u && groupLinks > 0u)
      groupBase = atomicAdd(counters.linksRequested, groupLinks);
    barrier();
    uint link = groupBase + offset;
    if (segments) {
      // Each list's links of the batch (front, then opaque; by class) run down consecutive links.
      for (uint slice = 0u; slice < slices; ++slice) {
        uvec2 sliceHits = slices == 1u ? hits : (slice == 0u ? frontHits : opaqueHits);
        uint heads = (tileIndex * slices + slice) * classes;
        for (uint c = 0u; c < classes; ++c)
          pushSegment(
              classes == 1u ? sliceHits : sliceHits & candidateBits(classFirst[c], classFirst[c + 1u]),
              heads + c, link);
      }
    } else {  // a link at each slice's head; past the pool's end counted, not written (the CPU grows it)
      for (uint word = 0u; word < 2u; ++word) {
        for (uint bits = hits[word]; bits != 0u && link < lll.params.x; bits &= bits - 1u) {
          uint i = word * 32u + uint(findLSB(bits));
          uint index = candidates[i] & ~kShapedCandidate;
          vec2 depths = candidateDepths[i];
          uvec2 lists = tileIndex * slices + depthSlicesOverlapping(range, depths.x, depths.y, split, zNear);
          uint lightClass = lightListClass(index);
          for (uint list = lists.x; list <= lists.y && link < lll.params.x; ++list, ++link)
            writeLink(link, index, depths.x, depths.y,
                      atomicExchange(tileHeads[list * classes + lightClass], link));
        }
      }
    }
    barrier();
  }
}
