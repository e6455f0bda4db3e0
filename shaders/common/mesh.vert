#version 460
// Shared by every pass that draws the scene: the same SPIR-V computing the same position gives the
// same depth in the prepass and in the shading passes that test EQUAL against it.
#include "common/draw_push.glsl"
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  vec4 world = draw.model * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outNormal = transpose(inverse(mat3(draw.model))) * inNormal;
  outUv = inUv;
  gl_Position = frame.viewProj * world;
}
