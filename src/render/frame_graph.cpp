#include "render/frame_graph.h"

#include <algorithm>
#include <stdexcept>

namespace lll {

namespace {

struct Access {
  VkPipelineStageFlags2 stages = 0;
  VkAccessFlags2 access = 0;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  bool reads = false;
  bool writes = false;
  bool discards = false;  // the earlier contents are not needed: a layout change may drop them
};

constexpr VkPipelineStageFlags2 kFragmentTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

bool isDepthFormat(VkFormat format) {
  return format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D32_SFLOAT_S8_UINT ||
         format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D16_UNORM;
}

}  // namespace

VkImageLayout sampledLayout(const Image& image) {
  return isDepthFormat(image.format()) ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL
                                       : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

namespace {

Access describe(const ResourceUse& u) {
  switch (u.use) {
    case Use::ColorWrite:
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
              false,
              true,
              true};
    case Use::ColorBlend:
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
              true,
              true,
              false};
    case Use::DepthWrite:
      return {kFragmentTests,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
              true,
              true,
              true};
    case Use::DepthReadWrite:
      return {kFragmentTests,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
              true,
              true,
              false};
    case Use::DepthTest:
      return {kFragmentTests,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
              VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL,
              true,
              false,
              false};
    case Use::DepthStencilWrite:
      return {kFragmentTests,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
              true,
              true,
              true};
    case Use::StencilWrite:
      return {kFragmentTests,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_STENCIL_ATTACHMENT_OPTIMAL,
              true,
              true,
              false};
    case Use::Sampled:
      // A depth image is sampled in the layout it is depth-tested in: both in one pass, no change.
      return {u.stages,
              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              u.image ? sampledLayout(*u.image) : VK_IMAGE_LAYOUT_UNDEFINED,
              true,
              false,
              false};
    case Use::StorageRead:
      return {u.stages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, VK_IMAGE_LAYOUT_GENERAL, true, false, false};
    case Use::StorageWrite:
      return {u.stages, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL, false, true, true};
    case Use::StorageReadWrite:
      return {u.stages,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
              VK_IMAGE_LAYOUT_GENERAL,
              true,
              true,
              false};
    case Use::TransferRead:
      return {VK_PIPELINE_STAGE_2_TRANSFER_BIT,
              VK_ACCESS_2_TRANSFER_READ_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
              true,
              false,
              false};
    case Use::TransferWrite:
      return {VK_PIPELINE_STAGE_2_TRANSFER_BIT,
              VK_ACCESS_2_TRANSFER_WRITE_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
              false,
              true,
              true};
    case Use::IndirectRead:
      return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
              VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED,
              true,
              false,
              false};
    case Use::HostRead:
      return {VK_PIPELINE_STAGE_2_HOST_BIT,
              VK_ACCESS_2_HOST_READ_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED,
              true,
              false,
              false};
  }
  throw std::logic_error("FrameGraph: unknown use");
}

}  // namespace

FrameGraph::FrameGraph(VkCommandBuffer cmd, PassTimer& timer) : cmd_(cmd), timer_(timer) {}

FrameGraph::State& FrameGraph::state(const void* resource) {
  for (State& s : states_)
    if (s.resource == resource) return s;
  // First use this frame: whatever the earlier submissions did with it must be done, and its
  // contents (images) are taken as undefined, so the first use must be one that writes them.
  State fresh;
  fresh.resource = resource;
  fresh.writeStages = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  fresh.writeAccess = VK_ACCESS_2_MEMORY_WRITE_BIT;
  states_.push_back(fresh);
  return states_.back();
}

void FrameGraph::produceOnFirstUse(const Image& image, std::function<void()> produce) {
  for (auto& [pending, p] : producers_)
    if (pending == &image) {
      p = std::move(produce);
      return;
    }
  producers_.emplace_back(&image, std::move(produce));
}

void FrameGraph::runProducers(const std::vector<ResourceUse>& uses) {
  for (const ResourceUse& u : uses) {
    if (!u.image) continue;
    auto found =
        std::find_if(producers_.begin(), producers_.end(), [&](const auto& p) { return p.first == u.image; });
    if (found == producers_.end()) continue;
    // Out of the list first: the producer's own steps use the image too.
    std::function<void()> produce = std::move(found->second);
    producers_.erase(found);
    produce();
  }
}

void FrameGraph::barriers(const std::vector<ResourceUse>& uses) {
  if (!producers_.empty()) runProducers(uses);
  // One access per resource: a pass using a resource two ways (a depth image tested and sampled,
  // a buffer read as indirect arguments and as storage) needs one barrier covering both, since
  // barriers in one call are not ordered against each other's layout transitions.
  std::vector<std::pair<ResourceUse, Access>> merged;
  for (const ResourceUse& u : uses) {
    const Access a = describe(u);
    auto same = std::find_if(merged.begin(), merged.end(), [&](const auto& m) {
      return m.first.image == u.image && m.first.buffer == u.buffer;
    });
    if (same == merged.end()) {
      merged.emplace_back(u, a);
      continue;
    }
    Access& b = same->second;
    if (u.image && b.layout != a.layout)
      throw std::logic_error("FrameGraph: one pass uses an image in two layouts");
    b.stages |= a.stages;
    b.access |= a.access;
    b.reads = b.reads || a.reads;
    b.writes = b.writes || a.writes;
    b.discards = b.discards && a.discards;
  }
  std::vector<VkImageMemoryBarrier2> images;
  std::vector<VkBufferMemoryBarrier2> buffers;
  for (const auto& [u, a] : merged) {
    State& s = state(u.image ? static_cast<const void*>(u.image) : static_cast<const void*>(u.buffer));
    const bool newLayout = u.image && s.layout != a.layout;
    VkPipelineStageFlags2 srcStages = 0;
    VkAccessFlags2 srcAccess = 0;
    if (a.writes || newLayout) {
      // After the last write and every read since (a layout change writes the image too).
      srcStages = s.writeStages | s.readStages;
      srcAccess = s.writeAccess;
    } else if (s.writeStages != 0 && ((a.stages & ~s.visibleStages) || (a.access & ~s.visibleAccess))) {
      srcStages = s.writeStages;  // the last write, not yet visible to this reader
      srcAccess = s.writeAccess;
    }
    if (srcStages != 0 || newLayout) {
      if (u.image) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = srcStages ? srcStages : VK_PIPELINE_STAGE_2_NONE;
        b.srcAccessMask = srcAccess;
        b.dstStageMask = a.stages;
        b.dstAccessMask = a.access;
        b.oldLayout =
            a.discards || s.layout == VK_IMAGE_LAYOUT_UNDEFINED ? VK_IMAGE_LAYOUT_UNDEFINED : s.layout;
        b.newLayout = a.layout;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = u.image->handle();
        b.subresourceRange = u.image->subresourceRange();
        images.push_back(b);
      } else {
        VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        b.srcStageMask = srcStages;
        b.srcAccessMask = srcAccess;
        b.dstStageMask = a.stages;
        b.dstAccessMask = a.access;
        b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.buffer = u.buffer->handle();
        b.offset = 0;
        b.size = VK_WHOLE_SIZE;
        buffers.push_back(b);
      }
    }
    if (u.image) s.layout = a.layout;
    if (a.writes) {
      s.writeStages = a.stages;
      s.writeAccess = a.access & (VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT |
                                  VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                  VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
      s.readStages = a.reads ? a.stages : 0;
      // A write is visible to no later command until a barrier makes it so, even one of the
      // same stage (a dispatch reading what the one before it wrote).
      s.visibleStages = 0;
      s.visibleAccess = 0;
    } else if (newLayout) {
      // The transition is a write of its own, done before this barrier's destination stages;
      // later readers in other stages wait for those (the write before it is available already).
      s.writeStages = a.stages;
      s.writeAccess = 0;
      s.readStages = a.stages;
      s.visibleStages = a.stages;
      s.visibleAccess = a.access;
    } else {
      s.readStages |= a.stages;
      if (srcStages != 0) {
        s.visibleStages |= a.stages;
        s.visibleAccess |= a.access;
      }
    }
  }
  if (images.empty() && buffers.empty()) return;
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = uint32_t(images.size());
  dependency.pImageMemoryBarriers = images.data();
  dependency.bufferMemoryBarrierCount = uint32_t(buffers.size());
  dependency.pBufferMemoryBarriers = buffers.data();
  vkCmdPipelineBarrier2(cmd_, &dependency);
}

void FrameGraph::pass(const std::string& name, const std::vector<ResourceUse>& uses,
                      const std::function<void(VkCommandBuffer)>& record) {
  barriers(uses);
  ScopedPass pass(timer_, cmd_, name);
  record(cmd_);
}

void FrameGraph::step(const std::vector<ResourceUse>& uses,
                      const std::function<void(VkCommandBuffer)>& record) {
  barriers(uses);
  record(cmd_);
}

}  // namespace lll
