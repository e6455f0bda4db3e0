#version 460
// The visibility pass's id for alpha-masked primitives, where the material's alpha passes.
#include "common/frame.glsl"
#include "common/texture_transform.glsl"

layout(constant_id = 20) const uint kTriangleBits = 16u;

layout(set = 1, binding = 0) uniform sampler2D baseColorTexture;

layout(push_constant) uniform VisibilityBlock {
  VisibilityPush visibility;
};

layout(location = 0) flat in uint inRecord;
layout(location = 1) in vec2 inUv;
layout(location = 2) in vec2 inUv1;
layout(location = 3) in float inAlpha;
layout(location = 0) out uint outId;

void main() {
  GpuMaterial m = materials[visibility.ids.y];
  TexCoordSets c = TexCoordSets(inUv, dFdx(inUv), dFdy(inUv), inUv1, dFdx(inUv1), dFdy(inUv1));
  vec4 texel = sampleSlot(baseColorTexture, m, 0u, c);
  if (m.baseColorFactor.a * inAlpha * texel.a < m.alpha.x) discard;
  outId = (inRecord << kTriangleBits) | uint(gl_PrimitiveID);
}
