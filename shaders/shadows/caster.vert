#version 460
// Shadow casters (src/shadows/shadow_casters.h): every opaque and alpha-masked primitive of the
// instances a view sees, drawn into the view's cell of a shadow atlas (a sun cascade, a spot light's
// cone, a face of a point light's cube). Alpha-masked ones go on to common/depth_mask.frag, which
// reads what common/mesh.vert would pass it; only the UVs and the colour's alpha matter.
#include "shared/shadow_types.h"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
layout(location = 8) in mat4 inModel;

layout(push_constant) uniform CasterBlock {
  CasterPush caster;
};

layout(location = 0) out vec3 outWorldPosition;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outTangent;
layout(location = 4) out vec2 outUv1;
layout(location = 5) out vec4 outColor;

void main() {
  vec4 world = inModel * vec4(inPosition, 1.0);
  outWorldPosition = world.xyz;
  outNormal = vec3(0.0, 0.0, 1.0);
  outUv = inUv;
  outTangent = vec4(1.0, 0.0, 0.0, 1.0);
  outUv1 = inUv1;
  outColor = inColor;
  gl_Position = caster.viewProj * world;
}
