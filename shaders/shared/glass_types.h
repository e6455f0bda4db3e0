// Glass shaded in compute (--glass compute, render/lit_passes.h), shared by C++ and GLSL: the
// glass-fragments pass stores every glass fragment that passes the depth test in a per-pixel list,
// and the glass pass lights each pixel's fragments through the technique's lighting interface and
// blends them over the frame, farthest first. Written once here; see shared.h for the rules.
#ifndef LLL_GLASS_TYPES_H
#define LLL_GLASS_TYPES_H
#include "shared/shared.h"

LLL_NAMESPACE_BEGIN

// Fragments a pixel blends at most: the nearest ones (GlassCounters.deepest says how many the
// deepest pixel had).
LLL_CONST(uint, kGlassLayers, 8u);
// The end of a pixel's list (glassHeads, glassNext).
LLL_CONST(uint, kGlassListEnd, 0xFFFFFFFFu);

// One glass fragment: its surface as the lights need it, and what needs no light (ambient,
// emission, the directional lights with the sun's shadow) computed by the fragment shader.
struct GlassFragment {
  vec4 positionDepth;      // world position, view depth
  vec4 normalAlpha;        // shading normal (facing the viewer's side), coverage
  vec4 baseColorMetallic;  // base colour, metallic
  vec4 unlitRoughness;     // ambient + emission + directional light, roughness
};
// Fragments at one depth blend in the order of their contents (glass_fragments' nearerGlass), so
// that the atomics' order never shows.
LLL_CHECK_SIZE(GlassFragment, 64);

struct GlassCounters {
  uint fragments;  // fragments the pass produced, also past `capacity` (afterFrame grows the pool)
  uint capacity;   // fragments the pool holds
  uint deepest;    // most fragments one pixel had
  uint pad;
};
LLL_CHECK_SIZE(GlassCounters, 16);

// The glass pass's indirect dispatch: one workgroup per group of kTileGroupSize^2 pixels that holds
// a glass fragment, listed by glass-groups (common/glass_groups.comp).
struct GlassGroupDispatch {
  uint groups;  // x: the groups listed
  uint y;       // 1
  uint z;       // 1
  uint pad;
};
LLL_CHECK_SIZE(GlassGroupDispatch, 16);

LLL_NAMESPACE_END

#endif
