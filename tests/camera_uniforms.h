#pragma once
// The frame uniforms of a camera as the renderer fills the fields the shadow code reads (view,
// near and far planes, the field of view's tangents), for tests that run that code on the CPU.
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include "shared/gpu_types.h"

namespace lll::test {

// A 16:9 camera at `eye` looking at `target`, vertical field of view 1 radian.
inline gpu::FrameUniforms cameraAt(glm::vec3 eye, glm::vec3 target, float near = 0.01f, float far = 60.0f) {
  gpu::FrameUniforms u{};
  u.view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
  const float tanHalf = std::tan(0.5f), aspect = 16.0f / 9.0f;
  u.depthParams = glm::vec4(near, far, tanHalf * aspect, tanHalf);
  return u;
}

}  // namespace lll::test
