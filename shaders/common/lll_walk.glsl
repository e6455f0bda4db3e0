// Lighting a surface from its tile's light list: the one function every shading pass calls
// (opaque, glass, particles). Needs common/material.glsl's Surface and the LLL bindings.
#ifndef LLL_WALK_GLSL
#define LLL_WALK_GLSL
#include "common/brdf.glsl"
#include "common/lll_data.glsl"

// Sum of the lights in the tile's list whose depth bounds contain `linearDepth`. The loop also stops
// after longestPossibleList() links, so a corrupt list can never hang the GPU.
vec3 shadeFromLightList(Surface s, uint tileIndex, float linearDepth) {
  vec3 color = vec3(0.0);
  uint link = tileHeads[tileIndex];
  for (uint guard = 0u; !isListEnd(link) && guard < longestPossibleList(); ++guard) {
    LightLink l = readLink(link);
    if (linearDepth >= l.minDepth && linearDepth <= l.maxDepth) color += evaluateLight(lights[l.light], s);
    link = l.next;
  }
  return color;
}

uint listLength(uint tileIndex) {
  uint count = 0u;
  uint link = tileHeads[tileIndex];
  for (; !isListEnd(link) && count < longestPossibleList(); ++count) link = readLink(link).next;
  return count;
}

#endif
