#include "shadows/shadow_raster.h"

#include <fmt/format.h>

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include "gpu/context.h"
#include "render/frame.h"
#include "render/gpu_scene.h"

namespace lll {

namespace {}  // namespace

std::string ShadowRaster::problem(const Context& context, uint32_t width, uint32_t height) {
  return RasterWorkspace::problem(context, width, height, fmt::format("a {}x{} shadow atlas", width, height));
}

ShadowRaster::ShadowRaster(Context& context, const GpuScene& scene, uint32_t width, uint32_t height,
                           uint32_t maxViews, std::string name, bool intoImage)
    : context_(context),
      scene_(scene),
      width_(width),
      height_(height),
      maxViews_(maxViews),
      name_(std::move(name)),
      intoImage_(intoImage) {
  const Scene& s = scene.scene();
  // One record per (instance, opaque primitive), single-sided first (their back faces are culled).
  std::vector<std::vector<const DrawItem*>> meshDraws(s.meshes.size());
  for (const DrawItem& d : scene.draws())
    if (s.materials[d.material].alphaMode == AlphaMode::Opaque) meshDraws[d.mesh].push_back(&d);
  std::vector<gpu::SurfaceRecord> records;
  std::vector<uint32_t> starts;
  for (const bool doubleSided : {false, true})
    for (uint32_t i = 0; i < s.instances.size(); ++i)
      for (const DrawItem* d : meshDraws[s.instances[i].mesh]) {
        if (s.materials[d->material].doubleSided != doubleSided) continue;
        records.push_back({d->firstIndex, d->vertexOffset, d->material, i});
        starts.push_back(triangles_);
        triangles_ += d->indexCount / 3;
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

  // Large triangles grow with the views: a list too short leaves the rest to one thread each, which
  // took 2.6 s for the atrium's 64 most important lights (354 views) on the H200. 2,048 a view,
  // within one storage buffer.
  const uint64_t mostLarge =
      (context.properties().limits.maxStorageBufferRange - 64) / sizeof(gpu::RasterTriangle);
  const uint32_t large =
      uint32_t(std::clamp<uint64_t>(uint64_t(maxViews) * 2048, RasterWorkspace::kLargeCapacity,
                                    std::max<uint64_t>(mostLarge, RasterWorkspace::kLargeCapacity)));
  work_ = RasterWorkspace(context, width, height, "shadow-raster", large, /*depthBuffer=*/!intoImage,
                          /*resolveResetsKeys=*/true);
  views_ = Buffer(context, sizeof(glm::uvec4) + std::max(1u, maxViews) * sizeof(gpu::ShadowRasterView),
                  kStorage, MemoryUse::Upload, name_ + "-views");
  setViews({});

  const char* resolve = intoImage ? "shadows/caster_resolve_image.comp" : "shadows/caster_resolve.comp";
  layout_ = PipelineLayout(context, {"shadows/caster_triangles.comp", "shadows/caster_bins.comp", resolve});
  trianglePipeline_ = Pipeline(context, layout_, "shadows/caster_triangles.comp");
  binPipeline_ = Pipeline(context, layout_, "shadows/caster_bins.comp");
  resolvePipeline_ = Pipeline(context, layout_, resolve);
}

void ShadowRaster::setViews(std::span<const ShadowView> views) {
  const uint32_t count = uint32_t(std::min<size_t>(views.size(), maxViews_));
  std::vector<gpu::ShadowRasterView> packed(count);
  cells_.clear();
  largestCell_ = 0;
  for (uint32_t v = 0; v < count; ++v) {
    packed[v] = {views[v].viewProj, views[v].reach, glm::uvec4(views[v].x, views[v].y, views[v].size, 0u)};
    cells_.push_back({{int32_t(views[v].x), int32_t(views[v].y)}, {views[v].size, views[v].size}});
    largestCell_ = std::max(largestCell_, views[v].size);
  }
  const glm::uvec4 header(count, width_, height_, 0u);
  views_.upload(&header, sizeof(header));
  if (count > 0) views_.upload(packed.data(), count * sizeof(gpu::ShadowRasterView), sizeof(header));
}

void ShadowRaster::record(FrameContext& frame, const Image& atlas) const {
  const uint32_t groups = divideRoundingUp(triangles_, RasterWorkspace::kGroupSize);
  const uint32_t groupsPerRow = std::max(1u, std::min(groups, 65535u));
  gpu::RasterPush push{};
  push.counts = glm::uvec4(triangles_, records_, singleSided_, groupsPerRow);
  // The visibility buffer's threshold for listing a triangle as large: also the fastest here (the H200,
  // bench/README.md: 256, 1024 and 4096 texels cost 0.05, 0.3 and 1.3 ms more with the sun alone).
  push.large = work_.largeParams(RasterWorkspace::kLargestOwnBox);
  DescriptorWriter writer;
  writer.storage(16, recordBuffer_.handle())
      .storage(17, instances_.handle())
      .storage(18, scene_.positionBuffer().handle())
      .storage(19, scene_.indexBuffer().handle())
      .storage(21, starts_.handle())
      .storage(26, views_.handle());
  work_.bind(writer);
  if (intoImage_) writer.image(30, atlas.view(), VK_IMAGE_LAYOUT_GENERAL);
  const auto bindAll = [&](VkCommandBuffer cmd, const Pipeline& pipeline) {
    pipeline.bind(cmd);
    writer.push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  };
  // Per view (workgroup z), over its cell's 8-texel tiles: one more in x and y where the cell's corner
  // is off the tiles' grid.
  const uint32_t tiles = divideRoundingUp(largestCell_, RasterWorkspace::kTileSize) + 1;
  const uint32_t views = uint32_t(cells_.size());
  work_.clear(frame.graph);
  frame.graph.pass(name_, work_.triangleUses(), [&](VkCommandBuffer cmd) {
    if (groups == 0) return;
    bindAll(cmd, trianglePipeline_);
    vkCmdDispatch(cmd, groupsPerRow, divideRoundingUp(groups, groupsPerRow), 1);
  });
  frame.graph.pass(name_ + "-bins", work_.binUses(), [&](VkCommandBuffer cmd) {
    bindAll(cmd, binPipeline_);
    vkCmdDispatch(cmd, RasterWorkspace::kBinningGroups, 1, 1);
  });
  std::vector<ResourceUse> resolveUses = work_.resolveUses();
  if (intoImage_) resolveUses.push_back(uses(atlas, Use::StorageWrite, kCompute));
  frame.graph.pass(name_ + "-resolve", resolveUses, [&](VkCommandBuffer cmd) {
    if (views == 0) return;
    bindAll(cmd, resolvePipeline_);
    vkCmdDispatch(cmd, tiles, tiles, views);
  });
  if (!intoImage_ && !cells_.empty()) work_.copyDepth(frame.graph, atlas, cells_, name_ + "-copy");
}

}  // namespace lll
