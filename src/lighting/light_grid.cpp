#include "lighting/light_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "core/errors.h"
#include "gpu/context.h"
#include "gpu/pipeline.h"
#include "gpu/vk_check.h"
#include "lighting/light_bins.h"
#include "render/frame.h"
#include "shared/grid_types.h"
#include "shared/lll_types.h"

namespace lll {

namespace {

// Initial index entries per tile (grown on overflow, grownCapacity).
constexpr uint64_t kInitialEntriesPerTile = 32;

uint32_t gridDebugView(DebugView view) {
  if (view == DebugView::Bounds)
    throw InputError("--debug-view bounds: the tiled and clustered techniques show none, heatmap or tiles");
  return debugViewCode(view);
}

class LightGrid final : public Technique {
 public:
  LightGrid(Context& context, const GpuScene& scene, const RenderSettings& settings,
            const FrameTargets& targets, const VisibilityBuffer* visibility, uint32_t slices);
  ~LightGrid() override { vkDestroySampler(context_.device(), depthSampler_, nullptr); }
  void buildLightData(FrameContext& frame) override;
  OpaqueShading opaqueShading() const override { return opaqueShading_; }
  LightingInterface lighting() const override;
  bool afterFrame() override;
  std::vector<std::pair<std::string, double>> stats() const override;
  LightGridLists read();

 private:
  void allocate(uint64_t entries);
  DescriptorWriter descriptors(const FrameContext& frame) const;

  Context& context_;
  OpaqueShading opaqueShading_;
  uint32_t tilesX_;
  uint32_t tilesY_;
  uint32_t tiles_;
  uint64_t maxEntries_;
  uint32_t overflows_ = 0;
  gpu::GridUniforms uniforms_{};
  gpu::GridCounters lastCounters_{};
  Buffer uniformBuffer_;
  Buffer tileRange_;
  Buffer clusters_;
  Buffer indices_;
  Buffer counters_;
  Buffer cursors_;
  LightBins bins_;
  VkSampler depthSampler_ = VK_NULL_HANDLE;
  PipelineLayout layout_;
  Pipeline tileRangePipeline_;
  Pipeline countPipeline_;
  Pipeline allocPipeline_;
  Pipeline writePipeline_;
  Pipeline finishPipeline_;
};

LightGrid::LightGrid(Context& context, const GpuScene& scene, const RenderSettings& settings,
                     const FrameTargets& targets, const VisibilityBuffer* visibility, uint32_t slices)
    : context_(context),
      opaqueShading_(visibility ? OpaqueShading::Visibility : OpaqueShading::GBuffer),
      tilesX_(divideRoundingUp(targets.width, settings.tileSize)),
      tilesY_(divideRoundingUp(targets.height, settings.tileSize)),
      tiles_(tilesX_ * tilesY_),
      maxEntries_(storageBufferCapacity(context, 4)) {
  validateTileSize(settings.tileSize);
  uniforms_.params =
      glm::uvec4(slices, 0, gridDebugView(settings.debugView), cellSplitsFor(context, scene.lightCount()));
  const VkBufferUsageFlags storage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  uniformBuffer_ = Buffer(context, sizeof(gpu::GridUniforms), storage, MemoryUse::Upload, "grid uniforms");
  tileRange_ = Buffer(context, uint64_t(tiles_) * 8, storage, MemoryUse::Device, "grid tile ranges");
  clusters_ = Buffer(context, uint64_t(tiles_) * slices * 8, storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     MemoryUse::Device, "grid clusters");
  cursors_ =
      Buffer(context, uint64_t(tiles_) * slices * 4, storage, MemoryUse::Device, "grid cluster cursors");
  counters_ = Buffer(context, sizeof(gpu::GridCounters), storage | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     MemoryUse::Readback, "grid counters");
  allocate(std::min(maxEntries_, uint64_t(tiles_) * kInitialEntriesPerTile));
  bins_ = LightBins(context, tilesX_, tilesY_, settings.tileSize, scene.lightCount());
  depthSampler_ = createNearestClampSampler(context);
  layout_ = PipelineLayout(context, {"lighting/grid/tile_range.comp", "lighting/grid/build.comp",
                                     "lighting/grid/grid_tiles.comp"});
  tileRangePipeline_ = Pipeline(context, layout_, "lighting/grid/tile_range.comp");
  countPipeline_ = Pipeline(context, layout_, "lighting/grid/build.comp", SpecializationConstants{{0, 0}});
  writePipeline_ = Pipeline(context, layout_, "lighting/grid/build.comp", SpecializationConstants{{0, 1}});
  allocPipeline_ =
      Pipeline(context, layout_, "lighting/grid/grid_tiles.comp", SpecializationConstants{{0, 0}});
  finishPipeline_ =
      Pipeline(context, layout_, "lighting/grid/grid_tiles.comp", SpecializationConstants{{0, 1}});
}

void LightGrid::allocate(uint64_t entries) {
  requireStorageBufferFits(context_, entries, 4, "the light grid's index array", "light indices",
                           "use fewer or smaller lights, a larger --tile or a lower resolution");
  uniforms_.params.y = uint32_t(std::max<uint64_t>(entries, 1));
  indices_ = Buffer(context_, uint64_t(uniforms_.params.y) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    MemoryUse::Device, "grid light indices");
}

DescriptorWriter LightGrid::descriptors(const FrameContext& frame) const {
  DescriptorWriter writer = meshPassDescriptors(frame);
  lighting().bind(writer);
  writer.storage(7, counters_.handle()).storage(8, cursors_.handle());
  bins_.bind(writer);
  return writer;
}

void LightGrid::buildLightData(FrameContext& frame) {
  uniformBuffer_.upload(&uniforms_, sizeof(uniforms_));
  frame.graph.pass("grid-clear", {uses(counters_, Use::TransferWrite), uses(clusters_, Use::TransferWrite)},
                   [&](VkCommandBuffer cmd) {
                     vkCmdFillBuffer(cmd, counters_.handle(), 0, VK_WHOLE_SIZE, 0);
                     vkCmdFillBuffer(cmd, clusters_.handle(), 0, VK_WHOLE_SIZE, 0);  // grid-count adds
                   });
  bins_.clear(frame);
  frame.graph.pass("grid-tile-range",
                   {uses(frame.targets.sampledDepth(), Use::Sampled, kCompute),
                    uses(tileRange_, Use::StorageWrite, kCompute), bins_.farDepthWrite(kCompute)},
                   [&](VkCommandBuffer cmd) {
                     tileRangePipeline_.bind(cmd);
                     descriptors(frame)
                         .image(9, frame.targets.sampledDepth().view(),
                                sampledLayout(frame.targets.sampledDepth()), depthSampler_)
                         .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
                     vkCmdDispatch(cmd, divideRoundingUp(tilesX_, gpu::kTileGroupSize),
                                   divideRoundingUp(tilesY_, gpu::kTileGroupSize), 1);
                   });
  bins_.build(frame);
  const uint32_t groupsX = divideRoundingUp(tilesX_, gpu::kTileGroupSize) * uniforms_.params.w;
  const uint32_t groupsY = divideRoundingUp(tilesY_, gpu::kTileGroupSize);
  const uint32_t tileGroups = divideRoundingUp(tiles_, 64);
  auto dispatch = [&](const char* name, const Pipeline& pipeline, std::vector<ResourceUse> used, uint32_t x,
                      uint32_t y) {
    frame.graph.pass(name, std::move(used), [&, x, y](VkCommandBuffer cmd) {
      pipeline.bind(cmd);
      descriptors(frame).push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
      vkCmdDispatch(cmd, x, y, 1);
    });
  };
  auto withBins = [&](std::vector<ResourceUse> used) {
    const std::vector<ResourceUse> binned = bins_.reads(kCompute);
    used.insert(used.end(), binned.begin(), binned.end());
    return used;
  };
  dispatch("grid-count", countPipeline_,
           withBins({uses(tileRange_, Use::StorageRead, kCompute),
                     uses(clusters_, Use::StorageReadWrite, kCompute)}),
           groupsX, groupsY);
  dispatch("grid-alloc", allocPipeline_,
           {uses(clusters_, Use::StorageReadWrite, kCompute), uses(cursors_, Use::StorageWrite, kCompute),
            uses(counters_, Use::StorageReadWrite, kCompute)},
           tileGroups, 1);
  dispatch(
      "grid-write", writePipeline_,
      withBins({uses(tileRange_, Use::StorageRead, kCompute), uses(clusters_, Use::StorageRead, kCompute),
                uses(cursors_, Use::StorageReadWrite, kCompute),
                uses(indices_, Use::StorageWrite, kCompute)}),
      groupsX, groupsY);
  dispatch("grid-finish", finishPipeline_,
           {uses(clusters_, Use::StorageReadWrite, kCompute), uses(cursors_, Use::StorageRead, kCompute),
            uses(counters_, Use::StorageReadWrite, kCompute)},
           tileGroups, 1);
  frame.graph.barriers({uses(counters_, Use::HostRead)});
}

LightingInterface LightGrid::lighting() const {
  return {"grid",
          [this](DescriptorWriter& writer) {
            writer.storage(3, uniformBuffer_.handle())
                .storage(4, tileRange_.handle())
                .storage(5, clusters_.handle())
                .storage(6, indices_.handle());
          },
          {&tileRange_, &clusters_, &indices_}};
}

bool LightGrid::afterFrame() {
  if (bins_.afterFrame()) return true;  // lights were left out of the build: draw again
  std::memcpy(&lastCounters_, counters_.mapped(), sizeof(lastCounters_));
  const uint64_t requested = lastCounters_.requested;
  if (requested <= uniforms_.params.y) return false;
  ++overflows_;
  allocate(grownCapacity(requested, maxEntries_));
  return true;
}

std::vector<std::pair<std::string, double>> LightGrid::stats() const {
  const double slices = uniforms_.params.x;
  std::vector<std::pair<std::string, double>> s = {
      {"tiles", double(tiles_)},
      {"slices_per_tile", slices},
      {"clusters", double(tiles_) * slices},
      {"index_entries_used", double(lastCounters_.requested)},
      {"index_capacity", double(uniforms_.params.y)},
      {"index_bytes", double(uniforms_.params.y) * 4.0},
      {"cluster_bytes", double(clusters_.size()) + double(cursors_.size()) + double(tileRange_.size())},
      {"workgroups_per_cell", double(uniforms_.params.w)},
      {"longest_cluster", double(lastCounters_.longest)},
      {"mean_cluster",
       double(lastCounters_.requested) / double(std::max(1u, lastCounters_.clustersWithLights))},
      {"clusters_with_lights", double(lastCounters_.clustersWithLights)},
      {"overflows", double(overflows_)},
      {"build_mismatches", double(lastCounters_.mismatches)},
  };
  const auto binned = bins_.stats();
  s.insert(s.end(), binned.begin(), binned.end());
  return s;
}

LightGridLists LightGrid::read() {
  const std::vector<uint32_t> ranges = readBackWords(context_, tileRange_),
                              clusters = readBackWords(context_, clusters_),
                              indices = readBackWords(context_, indices_);
  LightGridLists lists;
  lists.tilesX = tilesX_;
  lists.tilesY = tilesY_;
  lists.slices = uniforms_.params.x;
  for (uint32_t t = 0; t < tiles_; ++t) {
    glm::vec2 r;
    std::memcpy(&r, &ranges[2 * size_t(t)], sizeof(r));
    lists.tileRange.push_back(r);
  }
  const uint64_t capacity = uniforms_.params.y;
  for (size_t c = 0; c < size_t(tiles_) * lists.slices; ++c) {
    const uint64_t first = std::min<uint64_t>(clusters[2 * c], capacity);
    const uint64_t end = std::min<uint64_t>(first + clusters[2 * c + 1], capacity);
    lists.clusters.emplace_back(indices.begin() + first, indices.begin() + end);
  }
  return lists;
}

}  // namespace

LightGridLists readLightGrid(Technique& technique) {
  auto* grid = dynamic_cast<LightGrid*>(&technique);
  if (!grid) throw std::invalid_argument("readLightGrid needs the tiled or clustered technique");
  return grid->read();
}

std::unique_ptr<Technique> createLightGrid(Context& context, const GpuScene& scene,
                                           const RenderSettings& settings, const FrameTargets& targets,
                                           const VisibilityBuffer* visibility, uint32_t slices) {
  return std::make_unique<LightGrid>(context, scene, settings, targets, visibility, slices);
}

}  // namespace lll
