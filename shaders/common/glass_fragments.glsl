// glass-fragments (--glass compute, render/lit_passes.h): every glass fragment in front of the
// opaque depth is stored in its pixel's list with its surface and what needs no light (ambient,
// emission, the directional lights with the sun's shadow); lit/shade_glass.comp lights them in
// compute, where the H200 runs the same arithmetic far faster than in its few fragment units.
// Included by common/glass_fragments.frag (the depth attachment tests) and by
// common/glass_fragments_tested.frag (GLASS_TEST_DEPTH: no attachment; the fragment compares itself
// with the compute rasterizer's depth, so that frame needs no D32 copy of it).
#define GLASS_DATA_WRITE
#include "common/glass_data.glsl"
#include "common/mesh_fragment.glsl"

#ifdef GLASS_TEST_DEPTH
layout(set = 0, binding = 36) uniform texture2D opaqueDepth;  // R32F reverse-Z
#else
// No colour target and no depth writes: shade only what the depth pass left in front.
layout(early_fragment_tests) in;
#endif

void main() {
#ifdef GLASS_TEST_DEPTH
  // The attachment's test, GREATER_OR_EQUAL on the same value.
  if (gl_FragCoord.z < texelFetch(opaqueDepth, ivec2(gl_FragCoord.xy), 0).r) return;
#endif
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  uint node = atomicAdd(glassCounters.fragments, 1u);
  if (node >= glassCounters.capacity) return;  // counted: the pool grows and the frame is drawn again
  glassFragments[node] =
      GlassFragment(vec4(s.position, linearizeDepth(gl_FragCoord.z)), vec4(s.normal, s.alpha),
                    vec4(s.baseColor, s.metallic), vec4(unlistedLight(s), s.roughness));
  uvec2 at = uvec2(gl_FragCoord.xy);
  glassNext[node] = atomicExchange(glassHeads[at.y * uint(frame.viewport.x) + at.x], node);
  // The pixel's group marked for the glass pass: a plain store, which adds no wait to the fragment
  // (listing the group for an indirect dispatch, with a read and an atomic exchange, cost the H200
  // 0.010 ms of this pass at 1080p and 0.030 at 4K, more than it saved the glass pass).
  uvec2 groupAt = at / kTileGroupSize;
  glassGroupWords[groupAt.y * glassGroupsAcross() + groupAt.x] = 1u;
}
