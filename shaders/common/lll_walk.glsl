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
// The compute fill allocates a thread's links of a batch together, so a list mostly runs down
// consecutive links (link, link - 1, ...). Where the fill says so (lll.slicing.y) the walk reads the
// next kWalkAhead - 1 links below the current one with it, independent loads issued at once, and
// follows the chain through them while it stays consecutive: a list's walk waits for memory about
// once per kWalkAhead links instead of once per link. Links read ahead and not chained are unused.
const uint kWalkAhead = 4u;

bool nextListedLight(inout uint link, inout uint steps, float linearDepth, out uint light) {
  light = 0u;
  uint longest = longestPossibleList();
  bool ahead = lll.slicing.y != 0u;
  while (!isListEnd(link) && steps < longest) {
    uint base = link;
    LightLink run[kWalkAhead];
    for (uint k = 0u; k < kWalkAhead; ++k)
      if (k == 0u || ahead) run[k] = readLink(base >= k ? base - k : base);
    for (uint k = 0u; k < kWalkAhead; ++k) {
      LightLink l = run[k];
      link = l.next;
      ++steps;
      if (linearDepth >= l.minDepth && linearDepth <= l.maxDepth) {
        light = l.light;
        return true;
      }
      // The next link is the next one read only if the chain goes one down from this one.
      if (!ahead || isListEnd(link) || steps >= longest || link + k + 1u != base) break;
    }
  }
  return false;
}

uint listLength(uint list) {
  uint count = 0u;
  uint link = tileHeads[list];
  for (; !isListEnd(link) && count < longestPossibleList(); ++count) link = readLink(link).next;
  return count;
}

#endif
