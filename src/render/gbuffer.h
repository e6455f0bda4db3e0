#pragma once
// The thin G-buffer that techniques shading away from the geometry share ("deferred" lights it
// with light volumes, "lll --lll-shade compute" walks the light lists in a compute pass).
//   target0 RGBA8:   rgb base colour (sRGB-encoded by the shaders, common/gbuffer.glsl), a metallic
//   target1 RGBA16F: xyz world-space unit normal (facing the viewer), w roughness
// 12 B/px; position comes from the prepass depth. Ambient and emission need no light, so the pass
// writes them straight into the accumulation target (Infinity's forward-lit channels).
//
// With a visibility buffer (deferred) it is written by a compute pass from the rebuilt surfaces
// (common/gbuffer_visibility.comp), so the opaque geometry is not drawn again; without one, by
// drawing the scene with depth EQUAL the depth prepass.
#include "gpu/pipeline.h"
#include "gpu/resources.h"
#include "render/frame.h"

namespace lll {

class GBuffer {
 public:
  static constexpr VkFormat kFormat0 = VK_FORMAT_R8G8B8A8_UNORM;
  static constexpr VkFormat kFormat1 = VK_FORMAT_R16G16B16A16_SFLOAT;
  static constexpr double kBytesPerPixel = 4 + 8;

  GBuffer() = default;
  // `accumulationFormat`: the format of the target that record() writes ambient and emission to.
  // `sunInAccumulation`: whether the directional lights go into the accumulation with ambient and
  // emission (false: the technique lights them in a pass of its own).
  // `visibility`: the frame's visibility buffer to write it from in compute (deferred: then the
  // accumulation must be fp32 and without the sun), or null to draw the geometry.
  GBuffer(Context& context, const GpuScene& scene, const FrameTargets& targets,
          VkFormat accumulationFormat = kHdrFormat, bool sunInAccumulation = true,
          const VisibilityBuffer* visibility = nullptr);

  // Draws the opaque scene once (depth EQUAL the depth pass) into `accumulation` (cleared: ambient
  // and emission) and the two targets, as the frame-graph pass `passName`.
  void record(FrameContext& frame, const char* passName, const Image& accumulation) const;

  const Image& target0() const { return target0_; }
  const Image& target1() const { return target1_; }

 private:
  bool fromVisibility_ = false;
  PipelineLayout layout_;
  Pipeline pipeline_;
  Image target0_;
  Image target1_;
};

}  // namespace lll
