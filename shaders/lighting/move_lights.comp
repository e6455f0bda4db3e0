#version 460
// Moving lights on the GPU (render/moving_lights.h): each invocation places one animated light at
// the frame's time, writing only its position; the rest of the light array is as uploaded.
#include "shared/gpu_types.h"

layout(local_size_x = 64) in;

layout(std430, set = 0, binding = 0) buffer LightBlock {
  GpuLight lights[];
};
layout(std430, set = 0, binding = 1) readonly buffer MotionBlock {
  GpuLightMotion motions[];
};
layout(push_constant) uniform MovePush {
  vec4 seconds;  // x the time's first 12 significant bits, y the rest (x + y exact), z the time
  uvec4 range;   // x the first moving light, y how many
};

const float kTwoPi = 6.28318530717959;

// The fractional part of speed.x t + speed.y t: speed.x seconds.x and speed.x seconds.y are exact
// (12 by 12 and 12 by at most 12 significant bits), so only speed.y t's rounding, at most a few
// ten-millionths of a turn, remains; `precise` keeps the compiler from fusing them.
float turnsAt(vec2 speed) {
  precise float a = speed.x * seconds.x;
  precise float b = speed.x * seconds.y;
  precise float c = speed.y * seconds.z;
  precise float sum = fract(a) + fract(b) + fract(c);
  return sum;
}

// The dispatch is at most 65,535 groups wide (the least a device must allow): each invocation
// moves every (groups x 64)-th light from its own.
void main() {
  for (uint i = gl_GlobalInvocationID.x; i < range.y; i += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {
    GpuLightMotion m = motions[i];
    float orbit = kTwoPi * fract(turnsAt(m.orbit.xy) + m.orbit.z);
    float bob = kTwoPi * fract(turnsAt(m.bob.xy) + m.bob.z);
    float radius = m.centerRadius.w;
    vec3 offset = vec3(radius * cos(orbit), m.bob.w * sin(bob), radius * sin(orbit));
    lights[range.x + i].positionRange.xyz = m.centerRadius.xyz + offset;
  }
}
