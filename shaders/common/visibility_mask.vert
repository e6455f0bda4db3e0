#version 460
// The visibility pass, alpha-masked primitives: drawn one by one with their material, so the
// fragment shader can cut out texels below the cutoff as the depth prepass does.
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
layout(location = 8) in mat4 inModel;

layout(push_constant) uniform VisibilityBlock {
  VisibilityPush visibility;
};

layout(location = 0) flat out uint outRecord;
layout(location = 1) out vec2 outUv;
layout(location = 2) out vec2 outUv1;
layout(location = 3) out float outAlpha;

invariant gl_Position;

void main() {
  vec4 world = inModel * vec4(inPosition, 1.0);
  outRecord = visibility.ids.x + uint(gl_InstanceIndex - gl_BaseInstance);
  outUv = inUv;
  outUv1 = inUv1;
  outAlpha = inColor.a;
  gl_Position = frame.viewProj * world;
}
