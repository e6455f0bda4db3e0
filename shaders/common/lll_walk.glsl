// Lighting a surface from its tile's light list: the one function every shading pass calls
// (opaque, glass, particles). Needs common/material.glsl's Surface and the LLL bindings.
#ifndef LLL_WALK_GLSL
#define LLL_WALK_GLSL
#include "common/brdf.glsl"
#include "common/lll_data.glsl"

// The walk itself, as an iterator: start with link = tileHeads[list] and steps = 0; each call
// yields the next listed light whose depth bounds contain `linearDepth`, false at the list's end.
// It also stops after longestPossibleList() links, so a corrupt list can never hang the GPU.
//   uint link = tileHeads[listIndexOf(tile, depth)], steps = 0u, light;
//   while (nextListedLight(link, steps, depth, light)) ... lights[light] ...
bool nextListedLight(inout uint link, inout uint steps, float linearDepth, out uint light) {
  light = 0u;
  while (!isListEnd(link) && steps < longestPossibleList()) {
    LightLink l = readLink(link);
    link = l.next;
    ++steps;
    if (linearDepth >= l.minDepth && linearDepth <= l.maxDepth) {
      light = l.light;
      return true;
    }
  }
  return false;
}

// Links under one head (tileHeads[head]).
uint listLength(uint head) {
  uint count = 0u;
  uint link = tileHeads[head];
  for (; !isListEnd(link) && count < longestPossibleList(); ++count) link = readLink(link).next;
  return count;
}

#endif
