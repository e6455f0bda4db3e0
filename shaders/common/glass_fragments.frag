#version 460
// glass-fragments (--glass compute, render/lit_passes.h): every glass fragment in front of the
// opaque depth is stored in its pixel's list with its surface and what needs no light (ambient,
// emission, the directional lights with the sun's shadow); lit/shade_glass.comp lights them in
// compute, where the H200 runs the same arithmetic far faster than in its few fragment units.
#define GLASS_DATA_WRITE
#include "common/glass_data.glsl"
#include "common/mesh_fragment.glsl"

// No colour target and no depth writes: shade only what the depth pass left in front.
layout(early_fragment_tests) in;

void main() {
  GpuMaterial m = materials[draw.ids.x];
  Surface s = surfaceAtFragment(m);
  uint node = atomicAdd(glassCounters.fragments, 1u);
  if (node >= glassCounters.capacity) return;  // counted: the pool grows and the frame is drawn again
  glassFragments[node] =
      GlassFragment(vec4(s.position, linearizeDepth(gl_FragCoord.z)), vec4(s.normal, s.alpha),
                    vec4(s.baseColor, s.metallic), vec4(unlistedLight(s), s.roughness));
  uint pixel = uint(gl_FragCoord.y) * uint(frame.viewport.x) + uint(gl_FragCoord.x);
  glassNext[node] = atomicExchange(glassHeads[pixel], node);
}
