#version 460
// glass-groups (--glass compute, render/lit_passes.h): lists the 8x8-pixel groups that
// glass-fragments marked, for the glass pass's indirect dispatch, and clears their marks. A
// workgroup per group that left at once where there was no glass cost the H200 as much as the glass
// itself (0.038 ms at 1080p for ThreeL's 400-odd groups with glass of 32,400), a fixed set of
// workgroups striding over the groups left some with several heavy ones (5,144 VPLs' glass 1.08 ->
// 1.42 ms), and listing a group from the fragment shader that marked it first (a read and an atomic
// exchange a fragment) slowed glass-fragments by 25% at 4K.
#include "common/glass_data.glsl"

layout(local_size_x = 64) in;
// The glass pass's dispatch, then glass-light's (its y the lights' parts, set by the CPU).
layout(std430, set = 0, binding = 42) buffer GlassDispatchBlock {
  GlassGroupDispatch glassDispatch;
  GlassGroupDispatch glassPartsDispatch;
};

void main() {
  uint group = gl_GlobalInvocationID.x;
  if (group >= glassGroupCount() || glassGroupWords[group] == 0u) return;
  glassGroupWords[group] = 0u;
  glassGroupWords[glassGroupListed(atomicAdd(glassDispatch.groups, 1u))] = group;
  atomicAdd(glassPartsDispatch.groups, 1u);
}
