#version 460
// Shared by every pass that draws the scene: the same SPIR-V computing the same position gives the
// same depth in the prepass and in the shading passes that test EQUAL against it. Draws are
// instanced: each instance's transform and normal matrix come at instance rate (MeshInstance in
// shared/gpu_types.h, written in draw order by render/gpu_scene.cpp).
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 8) in mat4 inModel;
layout(location = 12) in mat3 inNormalMatrix;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;

void main() {
  vec4 world = inModel * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outNormal = inNormalMatrix * inNormal;
  outUv = inUv;
  gl_Position = frame.viewProj * world;
}
