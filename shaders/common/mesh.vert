#version 460
// Shared by every pass that draws the scene. The shading passes test EQUAL against the prepass's
// depth, so gl_Position is invariant: without it a driver may compile the same expression
// differently in two pipelines (fused or not), and an EQUAL test then drops pixels. Draws are
// instanced: each instance's transform and normal matrix come at instance rate (MeshInstance in
// shared/gpu_types.h, written in draw order by render/gpu_scene.cpp).
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;  // half floats (lll::Vertex::color)
layout(location = 8) in mat4 inModel;
// The normal matrix's columns with their w: the first's is the sign of the model's determinant
// (render/gpu_scene.cpp's normalMatrix), -1 where the transform mirrors.
layout(location = 12) in mat3x4 inNormalColumns;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outTangent;
layout(location = 4) out vec2 outUv1;
layout(location = 5) out vec4 outColor;

invariant gl_Position;

void main() {
  vec4 world = inModel * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outNormal = mat3(inNormalColumns) * inNormal;
  outUv = inUv;
  outUv1 = inUv1;
  outColor = inColor;
  // Tangents follow the surface (the model matrix, not the normal matrix); a mirroring transform
  // flips the bitangent's handedness (the sign computed once, on the CPU).
  outTangent = vec4(mat3(inModel) * inTangent.xyz, inTangent.w * inNormalColumns[0].w);
  gl_Position = frame.viewProj * world;
}
