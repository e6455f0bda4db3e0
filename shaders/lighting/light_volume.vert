#version 460
// A light's bounding volume: a unit shell vertex placed by the light's model matrix. The instance
// index selects the placed volume (techniques draw groups instanced, or one light at a time).
#include "common/frame.glsl"
#include "shared/deferred_types.h"

layout(std430, set = 0, binding = 3) readonly buffer VolumeBlock {
  LightVolume volumes[];
};
layout(location = 0) in vec3 inPosition;  // unit shell vertex

layout(location = 0) flat out uint outVolume;

// The pre-pass draws each volume twice, in a stencil-marking pipeline and in the shading pipeline
// that clears exactly those marks: both must rasterize the same pixels.
invariant gl_Position;

void main() {
  vec4 world = volumes[gl_InstanceIndex].model * vec4(inPosition, 1.0);
  gl_Position = frame.viewProj * world;
  outVolume = gl_InstanceIndex;
}
