#include "render/gbuffer.h"

#include <stdexcept>

#include "gpu/context.h"
#include "render/gpu_scene.h"
#include "render/visibility.h"

namespace lll {

GBuffer::GBuffer(Context& context, const GpuScene& scene, const FrameTargets& targets,
                 VkFormat accumulationFormat, bool sunInAccumulation, const VisibilityBuffer* visibility)
    : fromVisibility_(visibility != nullptr) {
  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_SAMPLED_BIT |
      (fromVisibility_ ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
  target0_ = Image(context, targets.width, targets.height, kFormat0, usage, "gbuffer0");
  target1_ = Image(context, targets.width, targets.height, kFormat1, usage, "gbuffer1");
  if (fromVisibility_) {
    // common/gbuffer_visibility.comp writes deferred's accumulation: fp32, without the sun.
    if (accumulationFormat != VK_FORMAT_R32G32B32A32_SFLOAT || sunInAccumulation)
      throw std::logic_error(
          "GBuffer: from the visibility buffer only into an fp32 accumulation without the sun");
    const SpecializationConstants constants = visibility->surfaceConstants(scene);
    const std::string shader = visibility->surfaceShader("common/gbuffer_visibility.comp");
    layout_ = PipelineLayout(context, {shader}, {scene.textureTableLayout()}, constants);
    pipeline_ = Pipeline(context, layout_, shader, constants);
    return;
  }
  layout_ = PipelineLayout(context, {"common/mesh.vert", "common/gbuffer.frag"}, {scene.materialSetLayout()});
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
  if (fromVisibility_) {
    frame.graph.pass(
        passName,
        {uses(accumulation, Use::StorageWrite, kCompute), uses(target0_, Use::StorageWrite, kCompute),
         uses(target1_, Use::StorageWrite, kCompute), uses(t.visibility, Use::StorageRead, kCompute)},
        [&](VkCommandBuffer cmd) {
          pipeline_.bind(cmd);
          DescriptorWriter writer = meshPassDescriptors(frame);
          writer.image(13, accumulation.view(), VK_IMAGE_LAYOUT_GENERAL)
              .image(14, target0_.view(), VK_IMAGE_LAYOUT_GENERAL)
              .image(15, target1_.view(), VK_IMAGE_LAYOUT_GENERAL);
          frame.visibility->bindSurfaceData(writer, frame);
          writer.push(frame.context, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
          const VkDescriptorSet textures = frame.scene.textureTable();
          vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.handle(), 1, 1, &textures, 0,
                                  nullptr);
          dispatchPerPixel(cmd, t);
        });
    return;
  }
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
