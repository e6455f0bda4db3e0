#include "lighting/light_bins.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

#include "core/errors.h"
#include "gpu/context.h"
#include "shared/limits.h"

namespace lll {

namespace {
// Initial entries per cell (grown on overflow, grownCapacity).
constexpr uint64_t kInitialEntriesPerCell = 64;
// Workgroups that bin the lights covering many cells (bin_lights.comp), 64 threads each: one per
// 512 lights, 256 to 2,048. With small dense lights most of them are large (H200, 1,048,576 lights,
// each binned in 11 cells on average: 256 groups took 0.44 ms to count them and the scatter 1.04,
// 2,048 groups 0.30 and 0.75).
uint32_t largeLightGroups(uint32_t lights) {
  return std::clamp<uint32_t>((lights + 511) / 512, 256, 2048);
}
}  // namespace

LightBins::LightBins(Context& context, uint32_t tilesX, uint32_t tilesY, uint32_t tileSize,
                     uint32_t lightCount)
    : context_(&context) {
  header_.cellsX = divideRoundingUp(tilesX, gpu::kTileGroupSize);
  header_.cellsY = divideRoundingUp(tilesY, gpu::kTileGroupSize);
  header_.cellPixels = tileSize * gpu::kTileGroupSize;
  header_.lightCount = lightCount;
  header_.unbinned = lightCount <= kUnbinnedLights ? 1 : 0;
  maxEntries_ = storageBufferCapacity(context, 4);
  const uint64_t cells = uint64_t(header_.cellsX) * header_.cellsY;
  headerBuffer_ = Buffer(context, sizeof(gpu::LightBinHeader),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                         MemoryUse::Readback, "light bins header");
  cells_ = Buffer(context, cells * sizeof(gpu::LightBinCell),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Device,
                  "light bins cells");
  largeLights_ = Buffer(context, std::max<uint64_t>(lightCount, 1) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        MemoryUse::Device, "light bins large lights");
  allocate(
      unbinned() ? 1 : std::min(maxEntries_, std::max<uint64_t>(cells * kInitialEntriesPerCell, lightCount)));
  if (unbinned()) {  // no bins' passes: the header, read by every build, is written once here
    context.submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdUpdateBuffer(cmd, headerBuffer_.handle(), 0, sizeof(header_), &header_);
    });
    return;
  }
  layout_ = PipelineLayout(context, {"lighting/bins/bin_lights.comp", "lighting/bins/bin_scan.comp"});
  count_ =
      Pipeline(context, layout_, "lighting/bins/bin_lights.comp", SpecializationConstants{{0, 0}, {1, 0}});
  countLarge_ =
      Pipeline(context, layout_, "lighting/bins/bin_lights.comp", SpecializationConstants{{0, 0}, {1, 1}});
  scatter_ =
      Pipeline(context, layout_, "lighting/bins/bin_lights.comp", SpecializationConstants{{0, 1}, {1, 0}});
  scan_ = Pipeline(context, layout_, "lighting/bins/bin_scan.comp");
}

void LightBins::allocate(uint64_t entries) {
  requireStorageBufferFits(*context_, entries, 4, "the light bins", "entries",
                           "use fewer or smaller lights, a larger --tile or a lower resolution");
  header_.capacity = uint32_t(std::max<uint64_t>(entries, 1));
  entries_ = Buffer(*context_, uint64_t(header_.capacity) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                    MemoryUse::Device, "light bins entries");
}

void LightBins::bind(DescriptorWriter& writer) const {
  writer.storage(11, headerBuffer_.handle()).storage(12, cells_.handle()).storage(13, entries_.handle());
}

ResourceUse LightBins::farDepthWrite(VkPipelineStageFlags2 stages) const {
  return uses(cells_, Use::StorageReadWrite, stages);
}

std::vector<ResourceUse> LightBins::reads(VkPipelineStageFlags2 stages) const {
  return {uses(headerBuffer_, Use::StorageRead, stages), uses(cells_, Use::StorageRead, stages),
          uses(entries_, Use::StorageRead, stages)};
}

void LightBins::clear(FrameContext& frame) {
  if (unbinned()) return;
  frame.graph.pass("bins-clear", {uses(headerBuffer_, Use::TransferWrite), uses(cells_, Use::TransferWrite)},
                   [&](VkCommandBuffer cmd) {
                     gpu::LightBinHeader header = header_;
                     header.requested = 0;
                     vkCmdUpdateBuffer(cmd, headerBuffer_.handle(), 0, sizeof(header), &header);
                     vkCmdFillBuffer(cmd, cells_.handle(), 0, VK_WHOLE_SIZE, 0);
                   });
}

void LightBins::build(FrameContext& frame) {
  if (unbinned()) return;
  auto writer = [&] {
    DescriptorWriter w = meshPassDescriptors(frame);
    bind(w);
    w.storage(14, largeLights_.handle());
    return w;
  };
  auto dispatch = [&](const char* name, const Pipeline& pipeline, std::vector<ResourceUse> used,
                      uint32_t groups) {
    frame.graph.pass(name, std::move(used), [&, groups](VkCommandBuffer cmd) {
      pipeline.bind(cmd);
      writer().push(*context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
      vkCmdDispatch(cmd, groups, 1, 1);
    });
  };
  const uint32_t lightGroups = divideRoundingUp(std::max(header_.lightCount, 1u), 64);
  dispatch("bins-count", count_,
           {uses(headerBuffer_, Use::StorageReadWrite, kCompute),
            uses(cells_, Use::StorageReadWrite, kCompute), uses(largeLights_, Use::StorageWrite, kCompute)},
           lightGroups);
  dispatch("bins-count-large", countLarge_,
           {uses(headerBuffer_, Use::StorageRead, kCompute), uses(cells_, Use::StorageReadWrite, kCompute),
            uses(largeLights_, Use::StorageRead, kCompute)},
           largeLightGroups(header_.lightCount));
  dispatch(
      "bins-scan", scan_,
      {uses(headerBuffer_, Use::StorageReadWrite, kCompute), uses(cells_, Use::StorageReadWrite, kCompute)},
      1);
  dispatch("bins-scatter", scatter_,
           {uses(headerBuffer_, Use::StorageRead, kCompute), uses(cells_, Use::StorageReadWrite, kCompute),
            uses(entries_, Use::StorageWrite, kCompute), uses(largeLights_, Use::StorageRead, kCompute)},
           lightGroups + largeLightGroups(header_.lightCount));
  frame.graph.barriers({uses(headerBuffer_, Use::HostRead)});
}

bool LightBins::afterFrame() {
  if (unbinned()) return false;
  gpu::LightBinHeader read{};
  std::memcpy(&read, headerBuffer_.mapped(), sizeof(read));
  lastRequested_ = read.requested;
  if (read.requested <= header_.capacity) return false;
  ++overflows_;
  allocate(grownCapacity(read.requested, maxEntries_));
  return true;
}

std::vector<std::pair<std::string, double>> LightBins::stats() const {
  return {{"bins_unbinned", unbinned() ? 1.0 : 0.0},
          {"bin_cells", double(header_.cellsX) * header_.cellsY},
          {"bin_entries_used", double(lastRequested_)},
          {"bin_entries_capacity", double(header_.capacity)},
          {"bin_bytes", double(header_.capacity) * 4.0 + double(cells_.size()) + double(largeLights_.size())},
          {"bin_overflows", double(overflows_)}};
}

}  // namespace lll
