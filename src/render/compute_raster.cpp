#include "render/compute_raster.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>

#include "gpu/context.h"
#include "render/gpu_scene.h"

namespace lll {

namespace {

constexpr uint32_t kTriangleBitsConstant = 20;  // as common/visibility.frag
constexpr VkDeviceSize kLargeHeader = 16;       // the count, padded to the entries' alignment
constexpr uint32_t kBinSize = 32;               // as kRasterBinSize in common/raster.glsl

VkDeviceSize keyBytes(uint32_t width, uint32_t height) {
  return VkDeviceSize(width) * height * sizeof(uint64_t);
}

}  // namespace

std::string RasterWorkspace::problem(const Context& context, uint32_t width, uint32_t height,
                                     const std::string& what) {
  if (!context.computeRasterFeatures())
    return fmt::format("{} lacks shaderInt64 or shaderBufferInt64Atomics", context.info().name);
  const VkDeviceSize limit = context.properties().limits.maxStorageBufferRange;
  if (keyBytes(width, height) > limit)
    return fmt::format("{} needs {} MiB of 64-bit keys, more than {}'s storage buffer limit ({} MiB)", what,
                       keyBytes(width, height) >> 20, context.info().name, limit >> 20);
  return {};
}

RasterWorkspace::RasterWorkspace(Context& context, uint32_t width, uint32_t height, const std::string& name,
                                 uint32_t largeCapacity, bool depthBuffer, bool resolveResetsKeys)
    : width_(width), height_(height), largeCapacity_(largeCapacity), resolveResetsKeys_(resolveResetsKeys) {
  constexpr VkBufferUsageFlags kCleared =
      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  keys_ = Buffer(context, keyBytes(width, height), kCleared, MemoryUse::Device, name + "-keys");
  // Clear from the start, for a resolve that resets the keys it reads instead of a clear each frame.
  if (resolveResetsKeys)
    context.submitAndWait(
        [&](VkCommandBuffer cmd) { vkCmdFillBuffer(cmd, keys_.handle(), 0, VK_WHOLE_SIZE, 0); });
  large_ = Buffer(context, kLargeHeader + VkDeviceSize(largeCapacity_) * sizeof(gpu::RasterTriangle),
                  kCleared, MemoryUse::Device, name + "-large-triangles");
  binsPerRow_ = divideRoundingUp(width, kBinSize);
  binCount_ = binsPerRow_ * divideRoundingUp(height, kBinSize);
  bins_ = Buffer(context, VkDeviceSize(binCount_) * (1 + kBinCapacity) * sizeof(uint32_t), kCleared,
                 MemoryUse::Device, name + "-bins");
  if (depthBuffer)
    depth_ = Buffer(context, VkDeviceSize(width) * height * sizeof(float),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Device,
                    name + "-depth");
}

DescriptorWriter& RasterWorkspace::bind(DescriptorWriter& writer) const {
  writer.storage(22, keys_.handle()).storage(23, large_.handle()).storage(25, bins_.handle());
  return depth_.handle() != VK_NULL_HANDLE ? writer.storage(24, depth_.handle()) : writer;
}

glm::uvec4 RasterWorkspace::largeParams(uint32_t largestOwnBox) const {
  return glm::uvec4(largeCapacity_, largestOwnBox, binsPerRow_, kBinCapacity);
}

void RasterWorkspace::clear(FrameGraph& graph) const {
  const bool keys = !resolveResetsKeys_;
  std::vector<ResourceUse> cleared = {uses(large_, Use::TransferWrite), uses(bins_, Use::TransferWrite)};
  if (keys) cleared.push_back(uses(keys_, Use::TransferWrite));
  graph.step(cleared, [&, keys](VkCommandBuffer cmd) {
    if (keys) vkCmdFillBuffer(cmd, keys_.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, large_.handle(), 0, kLargeHeader, 0);
    vkCmdFillBuffer(cmd, bins_.handle(), 0, VkDeviceSize(binCount_) * sizeof(uint32_t), 0);
  });
}

std::vector<ResourceUse> RasterWorkspace::triangleUses() const {
  return {uses(keys_, Use::StorageReadWrite, kCompute), uses(large_, Use::StorageReadWrite, kCompute),
          uses(bins_, Use::StorageReadWrite, kCompute)};
}

std::vector<ResourceUse> RasterWorkspace::binUses() const {
  return {uses(large_, Use::StorageRead, kCompute), uses(bins_, Use::StorageReadWrite, kCompute)};
}

std::vector<ResourceUse> RasterWorkspace::resolveUses() const {
  std::vector<ResourceUse> used = {
      uses(keys_, resolveResetsKeys_ ? Use::StorageReadWrite : Use::StorageRead, kCompute),
      uses(large_, Use::StorageRead, kCompute), uses(bins_, Use::StorageRead, kCompute)};
  if (depth_.handle() != VK_NULL_HANDLE) used.push_back(uses(depth_, Use::StorageWrite, kCompute));
  return used;
}

void RasterWorkspace::copyDepth(FrameGraph& graph, const Image& image, std::span<const VkRect2D> cells,
                                const std::string& name) const {
  std::vector<VkBufferImageCopy> copies;
  const VkRect2D whole{{0, 0}, {width_, height_}};
  for (const VkRect2D& cell : cells.empty() ? std::span<const VkRect2D>(&whole, 1) : cells) {
    VkBufferImageCopy& copy = copies.emplace_back();
    copy.bufferOffset = (VkDeviceSize(cell.offset.y) * width_ + VkDeviceSize(cell.offset.x)) * sizeof(float);
    copy.bufferRowLength = width_;
    copy.bufferImageHeight = height_;
    copy.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
    copy.imageOffset = {cell.offset.x, cell.offset.y, 0};
    copy.imageExtent = {cell.extent.width, cell.extent.height, 1};
  }
  const auto record = [this, &image, copies = std::move(copies)](VkCommandBuffer cmd) {
    vkCmdCopyBufferToImage(cmd, depth_.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           uint32_t(copies.size()), copies.data());
  };
  const std::vector<ResourceUse> copied = {uses(depth_, Use::TransferRead), uses(image, Use::TransferWrite)};
  if (name.empty())
    graph.step(copied, record);
  else
    graph.pass(name, copied, record);
}

std::string ComputeRaster::problem(const Context& context, uint32_t width, uint32_t height) {
  return RasterWorkspace::problem(context, width, height, fmt::format("{}x{}", width, height));
}

ComputeRaster::ComputeRaster(Context& context, uint32_t width, uint32_t height, uint32_t maxRecords,
                             uint32_t triangleBits)
    : context_(context),
      // The resolve reads every key once and resets it: no clear of 8 bytes a pixel each frame.
      work_(context, width, height, "raster", RasterWorkspace::kLargeCapacity, /*depthBuffer=*/true,
            /*resolveResetsKeys=*/true),
      largestOwnBox_(RasterWorkspace::kLargestOwnBox) {
  // LLL_RASTER_OWN_BOX overrides the threshold, for measuring it (bench/README.md).
  if (const char* own = std::getenv("LLL_RASTER_OWN_BOX"); own && *own)
    largestOwnBox_ = uint32_t(std::clamp(std::strtoul(own, nullptr, 10), 1ul, 1ul << 20));
  layout_ = PipelineLayout(
      context, {"common/raster_triangles.comp", "common/raster_bins.comp", "common/raster_resolve.comp"});
  triangles_ = Pipeline(context, layout_, "common/raster_triangles.comp",
                        SpecializationConstants{{kTriangleBitsConstant, triangleBits}});
  bins_ = Pipeline(context, layout_, "common/raster_bins.comp");
  resolve_ = Pipeline(context, layout_, "common/raster_resolve.comp");
  starts_ = Buffer(context, (VkDeviceSize(maxRecords) + 1) * sizeof(uint32_t),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUse::Upload, "raster-triangle-starts");
}

void ComputeRaster::record(FrameContext& frame, const Buffer& surfaceRecords, uint32_t records,
                           uint32_t singleSided, uint32_t triangles) {
  const FrameTargets& t = frame.targets;
  const GpuScene& scene = frame.scene;
  const uint32_t groups = divideRoundingUp(triangles, RasterWorkspace::kGroupSize);
  const uint32_t groupsPerRow = std::max(1u, std::min(groups, 65535u));
  gpu::RasterPush push{};
  push.counts = glm::uvec4(triangles, records, singleSided, groupsPerRow);
  push.large = work_.largeParams(largestOwnBox_);
  DescriptorWriter writer;
  writer.storage(0, frame.uniformBuffer.handle())
      .storage(16, surfaceRecords.handle())
      .storage(17, scene.frameInstances().handle())
      .storage(18, scene.positionBuffer().handle())
      .storage(19, scene.indexBuffer().handle())
      .storage(21, starts_.handle())
      .image(20, t.visibility.view(), VK_IMAGE_LAYOUT_GENERAL)
      .image(26, t.rasterDepth.view(), VK_IMAGE_LAYOUT_GENERAL);
  work_.bind(writer);
  const auto pushConstants = [&](VkCommandBuffer cmd) {
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  };

  work_.clear(frame.graph);
  frame.graph.pass("visibility", work_.triangleUses(), [&](VkCommandBuffer cmd) {
    if (groups == 0) return;
    triangles_.bind(cmd);
    writer.push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    pushConstants(cmd);
    vkCmdDispatch(cmd, groupsPerRow, divideRoundingUp(groups, groupsPerRow), 1);
  });
  frame.graph.pass("visibility-bins", work_.binUses(), [&](VkCommandBuffer cmd) {
    if (groups == 0) return;
    bins_.bind(cmd);
    writer.push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    pushConstants(cmd);
    vkCmdDispatch(cmd, RasterWorkspace::kBinningGroups, 1, 1);
  });
  frame.graph.pass(
      "visibility-resolve",
      work_.resolveUses() + std::vector<ResourceUse>{uses(t.visibility, Use::StorageWrite, kCompute),
                                                     uses(t.rasterDepth, Use::StorageWrite, kCompute)},
      [&](VkCommandBuffer cmd) {
        resolve_.bind(cmd);
        writer.push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
        pushConstants(cmd);
        vkCmdDispatch(cmd, divideRoundingUp(t.width, RasterWorkspace::kTileSize),
                      divideRoundingUp(t.height, RasterWorkspace::kTileSize), 1);
      });
  // The D32 depth only for passes that use it (a depth test, the masked primitives, a copy).
  depthCopied_ = false;
  frame.graph.produceOnFirstUse(t.depth, [this, &graph = frame.graph, &depth = t.depth] {
    work_.copyDepth(graph, depth);
    depthCopied_ = true;
  });
}

}  // namespace lll
