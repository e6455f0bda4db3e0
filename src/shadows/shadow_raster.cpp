#include "shadows/shadow_raster.h"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <vector>

#include "gpu/context.h"
#include "render/frame.h"
#include "render/gpu_scene.h"

namespace lll {

namespace {

// As the visibility buffer's rasterizer (render/compute_raster.cpp), measured there.
constexpr uint32_t kGroupSize = 64;         // caster_triangles.comp's workgroup
constexpr uint32_t kTileSize = 8;           // caster_resolve.comp's workgroup is kTileSize^2
constexpr uint32_t kLargeCapacity = 65536;  // listed large triangles; more are covered in place
constexpr uint32_t kLargestOwnBox = 64;     // texels a thread covers itself
constexpr VkDeviceSize kLargeHeader = 16;   // the count, padded to the entries' alignment
constexpr uint32_t kBinSize = 32;           // kRasterBinSize in common/raster.glsl
constexpr uint32_t kBinCapacity = 1024;     // listed triangles per bin; a fuller bin tests them all
constexpr uint32_t kBinningGroups = 1024;   // caster_bins.comp's workgroups, each taking every 1024th

VkDeviceSize keyBytes(uint32_t width, uint32_t height) {
  return VkDeviceSize(width) * height * sizeof(uint64_t);
}

}  // namespace

std::string ShadowRaster::problem(const Context& context, uint32_t width, uint32_t height) {
  if (!context.computeRasterFeatures())
    return fmt::format("{} lacks shaderInt64 or shaderBufferInt64Atomics", context.info().name);
  const VkDeviceSize limit = context.properties().limits.maxStorageBufferRange;
  if (keyBytes(width, height) > limit)
    return fmt::format(
        "a {}x{} shadow atlas needs {} MiB of 64-bit keys, more than {}'s storage buffer "
        "limit ({} MiB)",
        width, height, keyBytes(width, height) >> 20, context.info().name, limit >> 20);
  return {};
}

ShadowRaster::ShadowRaster(Context& context, const GpuScene& scene, uint32_t width, uint32_t height)
    : context_(context), scene_(scene), width_(width), height_(height) {
  const Scene& s = scene.scene();
  // One record per (instance, opaque primitive), single-sided first (their back faces are culled).
  std::vector<gpu::SurfaceRecord> records;
  std::vector<uint32_t> starts;
  for (const bool doubleSided : {false, true})
    for (uint32_t i = 0; i < s.instances.size(); ++i)
      for (const DrawItem& d : scene.draws()) {
        const Material& m = s.materials[d.material];
        if (d.mesh != s.instances[i].mesh || m.alphaMode != AlphaMode::Opaque || m.doubleSided != doubleSided)
          continue;
        records.push_back({d.firstIndex, d.vertexOffset, d.material, i});
        starts.push_back(triangles_);
        triangles_ += d.indexCount / 3;
        if (!doubleSided) ++singleSided_;
      }
  starts.push_back(triangles_);
  records_ = uint32_t(records.size());
  std::vector<gpu::MeshInstance> instances;
  for (const Instance& instance : s.instances) instances.push_back({instance.transform, {}});

  constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  recordBuffer_ = Buffer(context, std::max<size_t>(1, records.size()) * sizeof(gpu::SurfaceRecord), kStorage,
                         MemoryUse::Device, "shadow-caster-records");
  if (!records.empty()) recordBuffer_.upload(std::span<const gpu::SurfaceRecord>(records));
  starts_ =
      Buffer(context, starts.size() * sizeof(uint32_t), kStorage, MemoryUse::Device, "shadow-caster-starts");
  starts_.upload(std::span<const uint32_t>(starts));
  instances_ = Buffer(context, std::max<size_t>(1, instances.size()) * sizeof(gpu::MeshInstance), kStorage,
                      MemoryUse::Device, "shadow-caster-instances");
  if (!instances.empty()) instances_.upload(std::span<const gpu::MeshInstance>(instances));

  constexpr VkBufferUsageFlags kCleared = kStorage | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  keys_ = Buffer(context, keyBytes(width, height), kCleared, MemoryUse::Device, "shadow-raster-keys");
  large_ = Buffer(context, kLargeHeader + VkDeviceSize(kLargeCapacity) * sizeof(gpu::RasterTriangle),
                  kCleared, MemoryUse::Device, "shadow-raster-large-triangles");
  binsPerRow_ = divideRoundingUp(width, kBinSize);
  binCount_ = binsPerRow_ * divideRoundingUp(height, kBinSize);
  bins_ = Buffer(context, VkDeviceSize(binCount_) * (1 + kBinCapacity) * sizeof(uint32_t), kCleared,
                 MemoryUse::Device, "shadow-raster-bins");
  depth_ = Buffer(context, VkDeviceSize(width) * height * sizeof(float),
                  kStorage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::Device, "shadow-raster-depth");

  layout_ = PipelineLayout(
      context, {"shadows/caster_triangles.comp", "shadows/caster_bins.comp", "shadows/caster_resolve.comp"});
  trianglePipeline_ = Pipeline(context, layout_, "shadows/caster_triangles.comp");
  binPipeline_ = Pipeline(context, layout_, "shadows/caster_bins.comp");
  resolvePipeline_ = Pipeline(context, layout_, "shadows/caster_resolve.comp");
}

void ShadowRaster::record(FrameContext& frame, const Buffer& shadowUniforms, const Image& atlas) const {
  constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  const uint32_t groups = divideRoundingUp(triangles_, kGroupSize);
  const uint32_t groupsPerRow = std::max(1u, std::min(groups, 65535u));
  gpu::RasterPush push{};
  push.counts = glm::uvec4(triangles_, records_, singleSided_, groupsPerRow);
  push.large = glm::uvec4(kLargeCapacity, kLargestOwnBox, binsPerRow_, kBinCapacity);
  DescriptorWriter writer;
  writer.storage(16, recordBuffer_.handle())
      .storage(17, instances_.handle())
      .storage(18, scene_.positionBuffer().handle())
      .storage(19, scene_.indexBuffer().handle())
      .storage(21, starts_.handle())
      .storage(22, keys_.handle())
      .storage(23, large_.handle())
      .storage(24, depth_.handle())
      .storage(25, bins_.handle())
      .storage(26, shadowUniforms.handle());
  const auto bindAll = [&](VkCommandBuffer cmd, const Pipeline& pipeline) {
    pipeline.bind(cmd);
    writer.push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  };
  frame.graph.step(
      {uses(keys_, Use::TransferWrite), uses(large_, Use::TransferWrite), uses(bins_, Use::TransferWrite)},
      [&](VkCommandBuffer cmd) {
        vkCmdFillBuffer(cmd, keys_.handle(), 0, VK_WHOLE_SIZE, 0);
        vkCmdFillBuffer(cmd, large_.handle(), 0, kLargeHeader, 0);
        vkCmdFillBuffer(cmd, bins_.handle(), 0, VkDeviceSize(binCount_) * sizeof(uint32_t), 0);
      });
  frame.graph.pass(
      "shadow-sun",
      {uses(keys_, Use::StorageReadWrite, kCompute), uses(large_, Use::StorageReadWrite, kCompute),
       uses(bins_, Use::StorageReadWrite, kCompute)},
      [&](VkCommandBuffer cmd) {
        if (groups == 0) return;
        bindAll(cmd, trianglePipeline_);
        vkCmdDispatch(cmd, groupsPerRow, divideRoundingUp(groups, groupsPerRow), 1);
      });
  frame.graph.pass("shadow-sun-bins",
                   {uses(large_, Use::StorageRead, kCompute), uses(bins_, Use::StorageReadWrite, kCompute)},
                   [&](VkCommandBuffer cmd) {
                     bindAll(cmd, binPipeline_);
                     vkCmdDispatch(cmd, kBinningGroups, 1, 1);
                   });
  frame.graph.pass("shadow-sun-resolve",
                   {uses(keys_, Use::StorageRead, kCompute), uses(large_, Use::StorageRead, kCompute),
                    uses(bins_, Use::StorageRead, kCompute), uses(depth_, Use::StorageWrite, kCompute)},
                   [&](VkCommandBuffer cmd) {
                     bindAll(cmd, resolvePipeline_);
                     vkCmdDispatch(cmd, divideRoundingUp(width_, kTileSize),
                                   divideRoundingUp(height_, kTileSize), 1);
                   });
  frame.graph.step({uses(depth_, Use::TransferRead), uses(atlas, Use::TransferWrite)},
                   [&](VkCommandBuffer cmd) {
                     VkBufferImageCopy copy{};
                     copy.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
                     copy.imageExtent = {width_, height_, 1};
                     vkCmdCopyBufferToImage(cmd, depth_.handle(), atlas.handle(),
                                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
                   });
}

}  // namespace lll
