// The per-pixel lists of glass fragments (shared/glass_types.h): written by common/glass_fragments.frag,
// read by lit/shade_glass.comp. GLASS_DATA_WRITE makes the buffers writable.
#ifndef LLL_GLASS_DATA_GLSL
#define LLL_GLASS_DATA_GLSL
#include "shared/glass_types.h"

#ifdef GLASS_DATA_WRITE
#define GLASS_ACCESS
#else
#define GLASS_ACCESS readonly
#endif

// Each pixel's most recent fragment (row-major, frame.viewport.x wide), kGlassListEnd for none.
layout(std430, set = 0, binding = 32) GLASS_ACCESS buffer GlassHeadsBlock {
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

#endif
