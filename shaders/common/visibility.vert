#version 460
// The visibility pass (render/visibility.h), opaque primitives: positions alone, drawn in indirect
// multi-draws; each vertex passes on its surface record (this draw's first record plus which of
// the draw's instances it is). Invariant: the shading passes test depth against this pass.
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 8) in mat4 inModel;

layout(std430, set = 0, binding = 16) readonly buffer RecordBaseBlock {
  uint recordBases[];
};
layout(push_constant) uniform VisibilityBlock {
  VisibilityPush visibility;
};

layout(location = 0) flat out uint outRecord;

invariant gl_Position;

void main() {
  vec4 world = inModel * vec4(inPosition, 1.0);
  outRecord = recordBases[visibility.ids.z + gl_DrawID] + uint(gl_InstanceIndex - gl_BaseInstance);
  gl_Position = frame.viewProj * world;
}
