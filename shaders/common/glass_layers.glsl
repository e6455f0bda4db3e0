// What both compute glass passes (lit/shade_glass_parts, lit/shade_glass) read of a pixel's glass:
// its nearest kGlassLayers fragments in depth order, each one's surface, and the light each part of
// a layer's lights sent it (glassLight: with LightingInterface::listParts > 1, glass-light lights
// the parts on as many workgroups and the glass pass adds them up).
#ifndef LLL_GLASS_LAYERS_GLSL
#define LLL_GLASS_LAYERS_GLSL
#include "common/glass_data.glsl"
#include "common/material_surface.glsl"

// 0: the glass pass walks each layer's lights itself; P > 1: glass-light has lit each layer's P parts
// into glassLight[fragment * P + part].
layout(constant_id = 61) const uint kGlassLightParts = 0u;

#ifdef GLASS_LIGHT_WRITE
#define GLASS_LIGHT_ACCESS writeonly
#else
#define GLASS_LIGHT_ACCESS readonly
#endif
layout(std430, set = 0, binding = 43) GLASS_LIGHT_ACCESS buffer GlassLightBlock {
  vec4 glassLight[];  // rgb: a part's light on a fragment
};

// Whether fragment a (at depth da) blends after fragment b: nearer, or at the same depth first in
// the order of their contents, which does not depend on the order the fragments were stored in.
bool nearerGlass(uint a, float da, uint b, float db) {
  if (da != db) return da < db;
  GlassFragment fa = glassFragments[a], fb = glassFragments[b];
  vec4 ka[3] = vec4[3](fa.unlitRoughness, fa.baseColorMetallic, fa.normalAlpha);
  vec4 kb[3] = vec4[3](fb.unlitRoughness, fb.baseColorMetallic, fb.normalAlpha);
  for (int i = 0; i < 3; ++i)
    for (int c = 0; c < 4; ++c)
      if (ka[i][c] != kb[i][c]) return ka[i][c] < kb[i][c];
  return false;  // the same surface: either order blends the same
}

// The nearest kGlassLayers fragments of the list from `link`, nearest first (insertion: lists are
// short), and how many; `listed` counts them all.
uint nearestGlassLayers(uint link, out uint nodes[kGlassLayers], out uint listed) {
  float depths[kGlassLayers];
  uint count = 0u;
  listed = 0u;
  uint capacity = min(glassCounters.fragments, glassCounters.capacity);
  while (link != kGlassListEnd && link < capacity && listed < capacity) {
    float depth = glassFragments[link].positionDepth.w;
    ++listed;
    uint at = count < kGlassLayers ? count : kGlassLayers;
    while (at > 0u && nearerGlass(link, depth, nodes[at - 1u], depths[at - 1u])) {
      if (at < kGlassLayers) {
        depths[at] = depths[at - 1u];
        nodes[at] = nodes[at - 1u];
      }
      --at;
    }
    if (at < kGlassLayers) {
      depths[at] = depth;
      nodes[at] = link;
      count = min(count + 1u, kGlassLayers);
    }
    link = glassNext[link];
  }
  return count;
}

uint glassHeadIndex(uvec2 pixel) {
  return pixel.y * uint(frame.viewport.x) + pixel.x;
}

Surface glassSurface(GlassFragment f) {
  Surface s;
  s.position = f.positionDepth.xyz;
  s.view = normalize(frame.cameraPosition.xyz - s.position);
  s.normal = f.normalAlpha.xyz;
  s.alpha = f.normalAlpha.w;
  s.baseColor = f.baseColorMetallic.rgb;
  s.metallic = f.baseColorMetallic.w;
  s.roughness = f.unlitRoughness.w;
  s.occlusion = 1.0;
  s.emissive = vec3(0.0);
  return s;
}

// The first pixel of the group the workgroup serves (listed by glass-groups).
uvec2 glassGroupOrigin() {
  uint group = glassGroupWords[glassGroupListed(gl_WorkGroupID.x)];
  uint across = glassGroupsAcross();
  return uvec2(group % across, group / across) * kTileGroupSize;
}

#endif
