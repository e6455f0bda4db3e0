#include "render/frame.h"

#include <fmt/format.h>

#include <vector>

#include "core/errors.h"
#include "gpu/context.h"

#include "gpu/pipeline.h"
#include "shared/limits.h"
#include "shared/lll_types.h"

namespace lll {

void beginRendering(VkCommandBuffer cmd, uint32_t width, uint32_t height,
                    std::initializer_list<ColorTarget> colors, VkImageView depth, VkImageLayout depthLayout,
                    bool clearDepth) {
  std::vector<VkRenderingAttachmentInfo> colorInfos;
  for (const ColorTarget& c : colors) {
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = c.view;
    info.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    info.loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    info.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    info.clearValue.color = c.clearValue;
    colorInfos.push_back(info);
  }
  VkRenderingAttachmentInfo depthInfo{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depthInfo.imageView = depth;
  depthInfo.imageLayout = depthLayout;
  depthInfo.loadOp = clearDepth ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
  depthInfo.storeOp = depthLayout == VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL ? VK_ATTACHMENT_STORE_OP_STORE
                                                                              : VK_ATTACHMENT_STORE_OP_NONE;
  depthInfo.clearValue.depthStencil = {0.0f, 0};  // reverse-Z: far is 0
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, {width, height}};
  info.layerCount = 1;
  info.colorAttachmentCount = uint32_t(colorInfos.size());
  info.pColorAttachments = colorInfos.data();
  info.pDepthAttachment = depth ? &depthInfo : nullptr;
  vkCmdBeginRendering(cmd, &info);
  const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {width, height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

void validateTileSize(uint32_t tile) {
  if (tile == 0 || tile > gpu::kMaxTileSize || (tile & (tile - 1)) != 0)
    throw InputError(fmt::format("--tile {}: expected 1, 2, 4, 8 or 16", tile));
}

uint32_t debugViewCode(DebugView view) {
  switch (view) {
    case DebugView::None:
      return gpu::kDebugNone;
    case DebugView::Heatmap:
      return gpu::kDebugHeatmap;
    case DebugView::Bounds:
      return gpu::kDebugBounds;
    case DebugView::Tiles:
      return gpu::kDebugTiles;
  }
  throw std::invalid_argument("debugViewCode: not a DebugView");
}

void validateResolution(uint32_t width, uint32_t height) {
  if (width == 0 || height == 0 || width > gpu::kMaxImageSide || height > gpu::kMaxImageSide)
    throw InputError(fmt::format("resolution {}x{}: width and height must be between 1 and {}", width, height,
                                 gpu::kMaxImageSide));
}

DescriptorWriter meshPassDescriptors(const FrameContext& frame) {
  DescriptorWriter writer;
  writer.storage(0, frame.uniformBuffer.handle())
      .storage(1, frame.scene.lightBuffer().handle())
      .storage(2, frame.scene.materialBuffer().handle())
      .storage(51, frame.scene.lightBuffer().handle(), 0, kUniformLightRecordBytes);
  if (frame.shadows) frame.shadows->bind(writer);
  if (frame.lightShadows) frame.lightShadows->bind(writer);
  return writer;
}

void drawSceneIntoHdr(FrameContext& frame, const Pipeline& pipeline, const PipelineLayout& layout,
                      DrawFilter filter, bool clearHdr) {
  const FrameTargets& t = frame.targets;
  beginRendering(frame.cmd, t.width, t.height, {{t.hdr.view(), clearHdr}}, t.depth.view(),
                 VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, false);
  pipeline.bind(frame.cmd);
  meshPassDescriptors(frame).push(frame.context, frame.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
  frame.scene.draw(frame.cmd, layout.handle(), filter);
  vkCmdEndRendering(frame.cmd);
}

SpecializationConstants lightTypeConstants(const GpuScene& scene) {
  SpecializationConstants constants = lightTypeConstants(scene.scene());
  constants[41] = scene.shadowedLights() ? 1u : 0u;
  return constants;
}

SpecializationConstants lightTypeConstants(const Scene& scene) {
  bool spots = false, boxes = false, vpls = false;
  for (const Light& light : scene.lights) {
    spots |= light.type == LightType::Spot;
    boxes |= light.type == LightType::Box;
    vpls |= light.type == LightType::Vpl;
  }
  return {{30, spots ? 1u : 0u}, {31, boxes ? 1u : 0u}, {32, vpls ? 1u : 0u}};
}

void dispatchPerPixel(VkCommandBuffer cmd, const FrameTargets& targets) {
  vkCmdDispatch(cmd, divideRoundingUp(targets.width, gpu::kTileGroupSize),
                divideRoundingUp(targets.height, gpu::kTileGroupSize), 1);
}

uint64_t storageBufferCapacity(const Context& context, uint64_t bytesEach) {
  return context.properties().limits.maxStorageBufferRange / bytesEach;
}

void requireStorageBufferFits(const Context& context, uint64_t count, uint64_t bytesEach,
                              const std::string& what, const std::string& items, const std::string& advice) {
  const uint64_t limit = context.properties().limits.maxStorageBufferRange;
  if (count * bytesEach <= limit) return;
  throw InputError(
      fmt::format("{} {}: {} needs {:.1f} MiB in one storage buffer, but this device's largest "
                  "(maxStorageBufferRange) is {:.1f} MiB, which holds at most {} {}{}",
                  count, items, what, double(count * bytesEach) / 1048576.0, double(limit) / 1048576.0,
                  limit / bytesEach, items, advice.empty() ? "" : ": " + advice));
}

}  // namespace lll
