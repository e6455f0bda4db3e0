#include "render/gbuffer.h"

namespace lll {

GBuffer::GBuffer(Context& context, const GpuScene& scene, const FrameTargets& targets)
    : layout_(meshPassLayout(context, scene)) {
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  target0_ = Image(context, targets.width, targets.height, kFormat0, usage, "gbuffer0");
  target1_ = Image(context, targets.width, targets.height, kFormat1, usage, "gbuffer1");
  GraphicsPipelineDesc desc;
  desc.vertexShader = "common/mesh.vert";
  desc.fragmentShader = "common/gbuffer.frag";
  desc.colorFormats = {kHdrFormat, kFormat0, kFormat1};
  desc.depthFormat = kDepthFormat;
  desc.depthWrite = false;
  desc.depthCompare = VK_COMPARE_OP_EQUAL;  // one G-buffer write per pixel: the prepass decided
  pipeline_ = Pipeline(context, layout_, desc);
}

void GBuffer::record(FrameContext& frame, const char* passName, VkImageView accumulation) const {
  const FrameTargets& t = frame.targets;
  ScopedPass pass(frame.timer, frame.cmd, passName);
  for (const Image* image : {&target0_, &target1_})
    image->transition(frame.cmd, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  beginRendering(frame.cmd, t.width, t.height,
                 {{accumulation, true}, {target0_.view(), true}, {target1_.view(), true}}, t.depth.view(),
                 VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
  pipeline_.bind(frame.cmd);
  meshPassDescriptors(frame).push(frame.context, frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                                  layout_.handle());
  frame.scene.draw(frame.cmd, layout_.handle(), DrawFilter::Opaque);
  vkCmdEndRendering(frame.cmd);
  for (const Image* image : {&target0_, &target1_})
    image->transition(frame.cmd, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  memoryBarrier(frame.cmd, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
}

}  // namespace lll
