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
layout(location = 0) out uint outId;

void main() {
  GpuMaterial m = materials[visibility.ids.y];
  // As material.glsl's sampleSlot: implicit derivatives only of the input itself.
  vec2 dx = dFdx(inUv), dy = dFdy(inUv);
  vec4 texel = hasTextureTransform(m) ? textureGrad(baseColorTexture, textureCoordinates(m, 0u, inUv),
                                                    textureCoordinatesDerivative(m, 0u, dx),
                                                    textureCoordinatesDerivative(m, 0u, dy))
                                      : texture(baseColorTexture, inUv);
  if (m.baseColorFactor.a * texel.a < m.alpha.x) discard;
  outId = (inRecord << kTriangleBits) | uint(gl_PrimitiveID);
}
