// The per-pixel lists of glass fragments (shared/glass_types.h): written by common/glass_fragments.frag,
// read by lit/shade_glass.comp. GLASS_DATA_WRITE makes the fragments writable; the heads and the
// groups both passes write (the glass pass and glass-groups clear what they read).
#ifndef LLL_GLASS_DATA_GLSL
#define LLL_GLASS_DATA_GLSL
#include "common/frame.glsl"
#include "shared/glass_types.h"
#include "shared/limits.h"

#ifdef GLASS_DATA_WRITE
#define GLASS_ACCESS
#else
#define GLASS_ACCESS readonly
#endif

// Each pixel's most recent fragment (row-major, frame.viewport.x wide), kGlassListEnd for none;
// the glass pass sets its pixels' back to kGlassListEnd once read.
layout(std430, set = 0, binding = 32) buffer GlassHeadsBlock {
  uint glassHeads[];
};
layout(std430, set = 0, binding = 33) GLASS_ACCESS buffer GlassFragmentsBlock {
  GlassFragment glassFragments[];
};
// The fragment stored before each one at its pixel.
layout(std430, set = 0, binding = 34) GLASS_ACCESS buffer GlassNextBlock {
  uint glassNext[];
};
// Written by both passes (the fragments counted, the deepest pixel's count).
layout(std430, set = 0, binding = 35) buffer GlassCountersBlock {
  GlassCounters glassCounters;
};

// Groups of kTileGroupSize^2 pixels (row-major, glassGroupsAcross() wide): first a flag per group,
// glassGroupWords[group], 1 where glass-fragments stored a fragment; then the flagged groups listed
// by glass-groups, glassGroupWords[glassGroupListed(slot)] (GlassGroupDispatch.groups of them),
// which the glass pass runs over.
layout(std430, set = 0, binding = 41) buffer GlassGroupsBlock {
  uint glassGroupWords[];
};

uint glassGroupsAcross() {
  return (uint(frame.viewport.x) + kTileGroupSize - 1u) / kTileGroupSize;
}

uint glassGroupCount() {
  return glassGroupsAcross() * ((uint(frame.viewport.y) + kTileGroupSize - 1u) / kTileGroupSize);
}

uint glassGroupListed(uint slot) {
  return glassGroupCount() + slot;
}

#endif
