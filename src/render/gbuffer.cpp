#include "render/gbuffer.h"

namespace lll {

GBuffer::GBuffer(Context& context, const GpuScene& scene, const FrameTargets& targets,
                 VkFormat accumulationFormat, bool sunInAccumulation)
    : layout_(
          PipelineLayout(context, {"common/mesh.vert", "common/gbuffer.frag"}, {scene.materialSetLayout()})) {
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  target0_ = Image(context, targets.width, targets.height, kFormat0, usage, "gbuffer0");
  target1_ = Image(context, targets.width, targets.height, kFormat1, usage, "gbuffer1");
  GraphicsPipelineDesc desc;
  desc.vertexShader = "common/mesh.vert";
  desc.fragmentShader = "common/gbuffer.frag";
  desc.colorFormats = {accumulationFormat, kFormat0, kFormat1};
  desc.depthFormat = kDepthFormat;
  desc.depthWrite = false;
  desc.depthCompare = VK_COMPARE_OP_EQUAL;  // one G-buffer write per pixel: the prepass decided
  desc.constants = SpecializationConstants{{40, sunInAccumulation ? 1u : 0u}};
  pipeline_ = Pipeline(context, layout_, desc);
}

void GBuffer::record(FrameContext& frame, const char* passName, const Image& accumulation) const {
  const FrameTargets& t = frame.targets;
  frame.graph.pass(
      passName,
      {uses(accumulation, Use::ColorWrite), uses(target0_, Use::ColorWrite), uses(target1_, Use::ColorWrite),
       uses(t.depth, Use::DepthTest)},
      [&](VkCommandBuffer cmd) {
        beginRendering(cmd, t.width, t.height,
                       {{accumulation.view(), true}, {target0_.view(), true}, {target1_.view(), true}},
                       t.depth.view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
        pipeline_.bind(cmd);
        meshPassDescriptors(frame).push(frame.context, cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_);
        frame.scene.draw(cmd, layout_.handle(), DrawFilter::Opaque);
        vkCmdEndRendering(cmd);
      });
}

}  // namespace lll
