#version 460
#define PARTICLE_WRITES_ORDER
// First half of particles-sort: one (key, slot) pair per slot of the padded sort array. Visible
// particles get their view depth as a key that sorts far first; dead slots, particles outside the
// view frustum and padding get kParticleHiddenKey and sort last. Counts alive and visible ones.
#include "particles/particle_data.glsl"

layout(local_size_x = 64) in;
layout(push_constant) uniform SortBlock {
  SortPush sortPush;  // z: pairs in the sort array
};

bool insideFrustum(vec3 view, float radius) {
  float depth = -view.z;
  float near = frame.depthParams.x, far = frame.depthParams.y;
  vec2 tanHalf = frame.depthParams.zw;
  if (depth + radius < near || depth - radius > far) return false;
  // Distance outside each side plane, scaled by the plane normal's length.
  vec2 outside = abs(view.xy) - depth * tanHalf;
  return all(lessThanEqual(outside, radius * sqrt(1.0 + tanHalf * tanHalf)));
}

// The workgroup's counts, added to the counters once: a million invocations' atomics on the same two
// words cost most of particles-sort on the H200 (bench/README.md, 2026-12-03 seventh).
shared uint groupAlive, groupVisible;

void main() {
  if (gl_LocalInvocationIndex == 0u) {
    groupAlive = 0u;
    groupVisible = 0u;
  }
  barrier();
  uint index = gl_GlobalInvocationID.x;
  if (index < sortPush.step.z) {
    uvec2 pair = uvec2(kParticleHiddenKey, index);
    if (index < system.modes.z) {
      Particle p = particles[index];
      if (isAlive(p)) {
        atomicAdd(groupAlive, 1u);
        vec3 view = (frame.view * vec4(p.positionAge.xyz, 1.0)).xyz;
        if (insideFrustum(view, particleRadius(p))) {
          // Positive floats order like their bits; inverted, the farthest sorts first. The depth
          // is kept above zero so no key equals kParticleHiddenKey.
          pair.x = ~floatBitsToUint(max(-view.z, 1e-20));
          atomicAdd(groupVisible, 1u);
        }
      }
    }
    drawOrder[index] = pair;
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) {
    if (groupAlive > 0u) atomicAdd(particleCounters.alive.x, groupAlive);
    if (groupVisible > 0u) atomicAdd(particleCounters.dispatch.w, groupVisible);
  }
}
