#version 460
// Shared by every pass that draws the scene. The shading passes test EQUAL against the prepass's
// depth, so gl_Position is invariant: without it a driver may compile the same expression
// differently in two pipelines (fused or not), and an EQUAL test then drops pixels.
#include "common/draw_push.glsl"
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outTangent;

invariant gl_Position;

void main() {
  vec4 world = draw.model * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outNormal = transpose(inverse(mat3(draw.model))) * inNormal;
  outUv = inUv;
  // Tangents follow the surface (the model matrix, not the normal matrix); a mirroring transform
  // flips the bitangent's handedness.
  mat3 linear = mat3(draw.model);
  outTangent = vec4(linear * inTangent.xyz, inTangent.w * (determinant(linear) < 0.0 ? -1.0 : 1.0));
  gl_Position = frame.viewProj * world;
}
