// glass (--glass compute): each pixel's glass fragments (stored by common/glass_fragments.frag), the
// nearest kGlassLayers of them, lit through the technique's lighting interface and blended over the
// lit frame farthest first, as the raster path's premultiplied blend does draw by draw. A workgroup
// shades a group of 8x8 pixels (one of lll's lists per layer), only those with glass.
#include "common/glass_data.glsl"
#include "common/lighting.glsl"
#define LLL_DISPLAY_FROM_SHADING
#include "post/display.glsl"

layout(local_size_x = kTileGroupSize, local_size_y = kTileGroupSize) in;

layout(set = 0, binding = 13, rgba16f) uniform image2D hdr;

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

// Pixel `pixel`'s glass over what is behind it; its list head cleared for the next frame.
void shadeGlassPixel(uvec2 pixel) {
  // The nearest kGlassLayers fragments, nearest first (insertion: lists are short).
  uint nodes[kGlassLayers];
  float depths[kGlassLayers];
  uint count = 0u, listed = 0u;
  uint headIndex = pixel.y * uint(frame.viewport.x) + pixel.x;
  uint link = glassHeads[headIndex];
  glassHeads[headIndex] = kGlassListEnd;
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
  if (listed == 0u) return;
  atomicMax(glassCounters.deepest, listed);
  vec4 color = imageLoad(hdr, ivec2(pixel));
  for (uint i = count; i-- > 0u;) {
    GlassFragment f = glassFragments[nodes[i]];
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
    bool replaced;
    vec3 lit =
        lightingView(s, pixel, depths[i], f.unlitRoughness.rgb + lightSurface(s, pixel, depths[i]), replaced);
    float alpha = replaced ? 1.0 : s.alpha;
    color = vec4(lit * alpha, alpha) + color * (1.0 - alpha);  // premultiplied over
  }
  imageStore(hdr, ivec2(pixel), color);
  storeDisplay(ivec2(pixel), color.rgb);
}

// One workgroup per group of 8x8 pixels with glass (listed by glass-groups).
void main() {
  uint group = glassGroupWords[glassGroupListed(gl_WorkGroupID.x)];
  uint across = glassGroupsAcross();
  uvec2 pixel = uvec2(group % across, group / across) * kTileGroupSize + gl_LocalInvocationID.xy;
  if (pixel.x < uint(frame.viewport.x) && pixel.y < uint(frame.viewport.y)) shadeGlassPixel(pixel);
}
