// The Light Linked List's buffers (set 0, bindings 3..10) and the two operations on them: pushing
// a link at a list's head (fills) and walking a list (every shading pass). A tile has one list, or
// one per depth slice with --lll-slices (shared/depth_slices.h): list tile * slices + slice. With
// --vpl-interleave each of those is split by light class (listClasses() heads in a row, at
// list * listClasses() + class): the lights before the VPLs, then one class of VPLs each, so that a
// pixel that evaluates one class walks two short lists instead of one long one.
#ifndef LLL_DATA_GLSL
#define LLL_DATA_GLSL
#include "common/frame.glsl"
#include "shared/depth_slices.h"
#include "shared/lll_types.h"

// The pool's link format, kLinkCompact or kLinkWide (LightLinkedList::linkConstants): a
// specialization constant, so that a walk decodes its links without testing the format at each.
// ThreeL's frames on the H200 with the test compiled out (compact links only, 1080p): opaque
// shading 0.235 -> 0.216 ms at 16 lights, 2.458 -> 2.258 at 256 (bench/README.md, 2026-12-05).
layout(constant_id = 42) const uint kLinkFormat = 0u;

bool compactLinks() {
  return kLinkFormat == kLinkCompact;
}

// Shading passes only read the lists; fills define LLL_FILL_PASS to write them.
#ifdef LLL_FILL_PASS
#define LLL_LIST_ACCESS
#else
#define LLL_LIST_ACCESS readonly
#endif

layout(std430, set = 0, binding = 3) readonly buffer LllBlock {  // not uniform: see frame.glsl
  LllUniforms lll;
};
layout(std430, set = 0, binding = 4) LLL_LIST_ACCESS buffer HeadBlock {
  uint tileHeads[];
};
// Links as 32-bit words: 2 per compact link, 4 per wide link (layouts in shared/lll_types.h).
layout(std430, set = 0, binding = 5) LLL_LIST_ACCESS buffer LinkBlock {
  uint linkWords[];
};
// Shading passes must not see a writable buffer: lavapipe runs fragment shaders with side effects
// far slower. Fills and the stats pass (LLL_WRITES_COUNTERS) write the counters.
#if defined(LLL_FILL_PASS) || defined(LLL_WRITES_COUNTERS)
#define LLL_COUNTER_ACCESS
#else
#define LLL_COUNTER_ACCESS readonly
#endif
layout(std430, set = 0, binding = 6) LLL_COUNTER_ACCESS buffer CounterBlock {
  LllCounters counters;
};
// Nearest and farthest linear depth of each tile's opaque surfaces.
layout(std430, set = 0, binding = 7) LLL_LIST_ACCESS buffer TileRangeBlock {
  vec2 tileRange[];
};

// Lists per tile: 1, or the depth slices of --lll-slices.
uint listSlices() {
  return max(lll.slicing.x, 1u);
}

// Heads per list: 1, or 1 + K*K with --vpl-interleave K (above).
uint listClasses() {
  return max(lll.slicing.y, 1u);
}

// Which of a list's heads light `lightIndex` is pushed at: 0 for the lights before the VPLs (which
// end the light array from FrameUniforms' display.w), 1 + its class for a VPL.
uint lightListClass(uint lightIndex) {
  uint classes = listClasses();
  if (classes == 1u || lightIndex < frame.display.w) return 0u;
  return 1u + (lightIndex - frame.display.w) % (classes - 1u);
}

// The list that lights a point at `viewDepth` in tile `tileIndex` (its first head: listClasses() in
// a row).
uint listIndexOf(uint tileIndex, float viewDepth) {
  uint slices = listSlices();
  if (slices == 1u) return tileIndex;
  vec2 range = tileRange[tileIndex];
  return tileIndex * slices +
         depthSliceOf(range, viewDepth, lllSliceSplit(range, slices), frame.depthParams.x);
}

// Clamped to the grid: helper invocations beyond the image's right or bottom edge must still read
// a real list.
uint tileIndexOf(uvec2 pixel) {
  uint tile = frame.counts.y;
  uvec2 t = min(pixel / tile, frame.counts.zw - 1u);
  return t.y * frame.counts.z + t.x;
}

// A fill pushes at most one link per light into a tile's list, so no walk needs more steps than
// there are lights; with compact links at most kCompactLinkMaxLights, a constant that costs no load
// (ThreeL's opaque shading on the H100 at 1080p with uniform records: 0.1985 -> 0.1915 ms at 16
// lights, 2.106 -> 2.002 at 256; bench/README.md, 2026-12-06). Bounding walks by this rather than
// by the pool's size matters: inactive lanes of a fragment shader (lavapipe runs 4x4 blocks) may
// start from undefined values, and a walk bounded only by the pool then spins for the whole pool on
// a garbage chain while its block waits.
uint longestPossibleList() {
  return compactLinks() ? kCompactLinkMaxLights : min(lll.params.x, frame.counts.x);
}

// fp16 of a depth rounded towards -infinity / +infinity, so a compact link's bounds only widen.
uint halfRoundedDown(float value) {
  uint h = packHalf2x16(vec2(value, 0.0)) & 0xFFFFu;
  if (unpackHalf2x16(h).x > value) h = (h & 0x8000u) != 0u ? h + 1u : (h == 0u ? 0x8001u : h - 1u);
  return h;
}

uint halfRoundedUp(float value) {
  uint h = packHalf2x16(vec2(value, 0.0)) & 0xFFFFu;
  if (unpackHalf2x16(h).x < value) h = (h & 0x8000u) != 0u ? (h == 0x8000u ? 1u : h - 1u) : h + 1u;
  return h;
}

#ifdef LLL_FILL_PASS
// Writes link `link` (already allocated, inside the pool) in the pool's format.
void writeLink(uint link, uint lightIndex, float minDepth, float maxDepth, uint next) {
  if (compactLinks()) {
    uint depths = halfRoundedDown(max(minDepth, 0.0)) | (halfRoundedUp(maxDepth) << 16);
    linkWords[2u * link] = depths;
    linkWords[2u * link + 1u] = (lightIndex << 24) | (next & kCompactLinkEnd);
  } else {
    uint base = 4u * link;
    linkWords[base] = floatBitsToUint(max(minDepth, 0.0));
    linkWords[base + 1u] = floatBitsToUint(maxDepth);
    linkWords[base + 2u] = lightIndex;
    linkWords[base + 3u] = next;
  }
}

// The run of a tile's lists that a light with these depth bounds belongs in: every slice a point
// within the bounds can fall in (the walk finds a point's slice with the same function).
uvec2 listsOverlapping(uint tileIndex, float minDepth, float maxDepth) {
  uint slices = listSlices();
  if (slices == 1u) return uvec2(tileIndex);
  vec2 range = tileRange[tileIndex];
  return tileIndex * slices +
         depthSlicesOverlapping(range, minDepth, maxDepth, lllSliceSplit(range, slices), frame.depthParams.x);
}

// Allocates links and pushes one at the head of each of the tile's lists the light's depth bounds
// overlap (LIFO), as the raster fills do: any number of fragments may push into one tile at once.
// Past the pool's end the counter still counts, so the CPU learns the size the pool must grow to;
// nothing is written. One link per increment of 1: a GPU's compiler can merge a constant increment
// of one address across a subgroup into one atomic, which it cannot for a count that differs per
// fragment (the slices each overlaps), and every fragment of every light hits this one counter.
void pushLink(uint tileIndex, uint lightIndex, float minDepth, float maxDepth) {
  uvec2 lists = listsOverlapping(tileIndex, minDepth, maxDepth);
  uint classes = listClasses(), lightClass = lightListClass(lightIndex);
  for (uint list = lists.x; list <= lists.y; ++list) {
    uint link = atomicAdd(counters.linksRequested, 1u);
    if (link < lll.params.x)
      writeLink(link, lightIndex, minDepth, maxDepth,
                atomicExchange(tileHeads[list * classes + lightClass], link));
  }
}
#endif

struct LightLink {
  float minDepth;
  float maxDepth;
  uint light;
  uint next;
};

bool isListEnd(uint link) {
  // Compact: a head's kLinkEnd or a link's 24-bit end (no pool reaches kCompactLinkEnd links).
  return compactLinks() ? link >= kCompactLinkEnd : link == kLinkEnd;
}

LightLink readLink(uint link) {
  LightLink l;
  if (compactLinks()) {
    vec2 depths = unpackHalf2x16(linkWords[2u * link]);
    uint indexNext = linkWords[2u * link + 1u];
    l.minDepth = depths.x;
    l.maxDepth = depths.y;
    l.light = indexNext >> 24;
    l.next = indexNext & kCompactLinkEnd;
  } else {
    uint base = 4u * link;
    l.minDepth = uintBitsToFloat(linkWords[base]);
    l.maxDepth = uintBitsToFloat(linkWords[base + 1u]);
    l.light = linkWords[base + 2u];
    l.next = linkWords[base + 3u];
  }
  return l;
}

#endif
