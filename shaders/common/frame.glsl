// Bindings every mesh-shading pass shares (set 0 = push descriptors, set 1 = material textures).
#ifndef LLL_FRAME_GLSL
#define LLL_FRAME_GLSL
#include "shared/gpu_types.h"

layout(set = 0, binding = 0) uniform FrameBlock {
  FrameUniforms frame;
};
layout(std430, set = 0, binding = 1) readonly buffer LightBlock {
  GpuLight lights[];
};
layout(std430, set = 0, binding = 2) readonly buffer MaterialBlock {
  GpuMaterial materials[];
};

// View-space distance along the camera axis of a reverse-Z depth value (finite far plane).
float linearizeDepth(float depth) {
  float n = frame.depthParams.x;
  float f = frame.depthParams.y;
  return n * f / (depth * (f - n) + n);
}

#endif
