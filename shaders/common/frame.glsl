// Bindings every mesh-shading pass shares (set 0 = push descriptors, set 1 = material textures).
#ifndef LLL_FRAME_GLSL
#define LLL_FRAME_GLSL
#include "shared/gpu_types.h"

// Per-frame and per-system constants are read from storage buffers, not uniform blocks: lavapipe
// (Mesa 22.3) compiles a new variant of a shader with the values of its uniform blocks folded in,
// on every bind of a shader whose branches depend on them, and never frees the old one (about 1 MB
// a bind, every frame). It folds in nothing from storage buffers.
layout(std430, set = 0, binding = 0) readonly buffer FrameBlock {
  FrameUniforms frame;
};
layout(std430, set = 0, binding = 1) readonly buffer LightBlock {
  GpuLight lights[];
};
// Binding 51: the first kUniformLightRecords of the same records as a uniform block, for the
// interfaces that read them so (lighting/lll/lighting.glsl's lightRecord).
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
