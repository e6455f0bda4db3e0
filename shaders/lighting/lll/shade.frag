#version 460
// Shading with the light linked list: each pixel walks its tile's list. Used for opaque surfaces
// and, with blending, for glass at its own depth. Debug views replace the radiance.
#include "common/debug_colors.glsl"
#include "common/lll_walk.glsl"
#include "common/material.glsl"

layout(location = 0) in vec3 inWorldPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 0) out vec4 outColor;
// No depth writes and no side effects: shade only what the prepass left visible.
layout(early_fragment_tests) in;

// As ThreeL's view: a listed light's colour where it reaches the surface, grey where the list has
// it but the surface is out of its range (the cost of a coarse shape), black with no list entry.
vec3 boundsView(Surface s, uint tileIndex, float depth) {
  vec3 reached = vec3(0.0);
  bool listed = false;
  uint link = tileHeads[tileIndex];
  for (uint guard = 0u; !isListEnd(link) && guard < lll.params.x; ++guard) {
    LightLink l = readLink(link);
    if (depth >= l.minDepth && depth <= l.maxDepth) {
      listed = true;
      GpuLight light = lights[l.light];
      if (any(greaterThan(evaluateLight(light, s), vec3(0.0))))
        reached = max(reached, light.colorIntensity.rgb);
    }
    link = l.next;
  }
  return any(greaterThan(reached, vec3(0.0))) ? reached : (listed ? vec3(0.25) : vec3(0.0));
}

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = sampleSurface(m, inWorldPosition, inNormal, inUv, gl_FrontFacing);
  if (m.flags.x == kAlphaMask && s.alpha < m.alpha.x) discard;
  uint tileIndex = tileIndexOf(uvec2(gl_FragCoord.xy));
  float depth = linearizeDepth(gl_FragCoord.z);
  float alpha = m.flags.x == kAlphaBlend ? s.alpha : 1.0;
  uint view = lll.params.z;
  vec3 color;
  if (view == kDebugHeatmap) {
    uint count = listLength(tileIndex);
    color = count == 0u ? vec3(0.0) : heat(float(count) / float(frame.display.y));
    alpha = 1.0;
  } else if (view == kDebugBounds) {
    color = boundsView(s, tileIndex, depth);
    alpha = 1.0;
  } else {
    color = ambientAndEmissive(s) + shadeFromLightList(s, tileIndex, depth);
    if (view == kDebugTiles) {
      uvec2 inTile = uvec2(gl_FragCoord.xy) % frame.counts.y;
      if (inTile.x == 0u || inTile.y == 0u) color = vec3(1.0, 1.0, 0.0);
    }
  }
  outColor = vec4(color * alpha, alpha);
}
