#pragma once
// The frame as a list of passes that declare what they touch: each pass names the images and
// buffers it reads and writes and how (as a colour or depth attachment, sampled, as storage, by
// transfer, as indirect arguments), and the graph derives every barrier and layout transition
// from those declarations and the resources' tracked state before the pass records. Passes run in
// the order they are added (the frame is short and its order is its meaning); each is GPU-timed
// under its name.
//
// Within one pass, barriers between its own steps (a sort's merge stages, a shell fill's batches)
// are the pass's business; between passes none is written by hand.
#include <vulkan/vulkan.h>

#include <functional>
#include <string>
#include <vector>

#include "gpu/pass_timer.h"
#include "gpu/resources.h"

namespace lll {

// How a pass uses a resource.
enum class Use {
  ColorWrite,         // colour attachment, overwritten or cleared (earlier contents not needed)
  ColorBlend,         // colour attachment, loaded and blended over
  DepthWrite,         // depth attachment, cleared and written
  DepthTest,          // depth attachment, read-only test
  DepthReadWrite,     // depth attachment, loaded, tested and written
  DepthStencilWrite,  // depth-stencil attachment, cleared and written
  StencilWrite,       // depth-stencil attachment: depth tested read-only, stencil written
  Sampled,            // sampled image or texel fetch, in `stages`
  StorageRead,        // storage image or buffer, read in `stages`
  StorageWrite,       // storage image or buffer, written in `stages` (earlier contents not needed)
  StorageReadWrite,   // storage image or buffer, read and written in `stages`
  TransferRead,       // source of a copy
  TransferWrite,      // destination of a copy or fill
  IndirectRead,       // indirect draw or dispatch arguments
  HostRead,           // read by the CPU after the frame's submission
};

struct ResourceUse {
  const Image* image = nullptr;
  const Buffer* buffer = nullptr;
  Use use;
  VkPipelineStageFlags2 stages = 0;  // for Sampled and Storage*: the shader stages
};

inline ResourceUse uses(const Image& image, Use use, VkPipelineStageFlags2 stages = 0) {
  return {&image, nullptr, use, stages};
}
inline ResourceUse uses(const Buffer& buffer, Use use, VkPipelineStageFlags2 stages = 0) {
  return {nullptr, &buffer, use, stages};
}

// Two passes' worth of uses as one list (a pass's own, then its lighting interface's).
inline std::vector<ResourceUse> operator+(std::vector<ResourceUse> a, const std::vector<ResourceUse>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The layout a pass's descriptor names for `image` sampled (Use::Sampled): depth images are
// sampled in the layout they are depth-tested in.
VkImageLayout sampledLayout(const Image& image);

class FrameGraph {
 public:
  FrameGraph(VkCommandBuffer cmd, PassTimer& timer);

  // Emits the barriers `uses` need, then records `record` as a GPU-timed pass named `name`.
  void pass(const std::string& name, const std::vector<ResourceUse>& uses,
            const std::function<void(VkCommandBuffer)>& record);
  // As pass(), without a timestamp pair: a step of the frame too small to time on its own.
  void step(const std::vector<ResourceUse>& uses, const std::function<void(VkCommandBuffer)>& record);

  // Barriers for `uses` alone, for steps inside a pass that need them between their own commands.
  void barriers(const std::vector<ResourceUse>& uses);

  // Records `produce` (which adds its own steps or passes) just before the first later pass, step
  // or barrier that uses `image`, and not at all if none does: for work only some frames need (the
  // compute rasterizer's depth copied into the D32 image for passes that depth-test). One pending
  // producer per image; a second replaces the first.
  void produceOnFirstUse(const Image& image, std::function<void()> produce);

  VkCommandBuffer commandBuffer() const { return cmd_; }

 private:
  struct State {
    const void* resource = nullptr;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 writeStages = 0;  // the last write
    VkAccessFlags2 writeAccess = 0;
    VkPipelineStageFlags2 readStages = 0;     // reads since the last write
    VkPipelineStageFlags2 visibleStages = 0;  // where the last write is visible already
    VkAccessFlags2 visibleAccess = 0;
  };
  State& state(const void* resource);
  void runProducers(const std::vector<ResourceUse>& uses);

  VkCommandBuffer cmd_;
  PassTimer& timer_;
  std::vector<State> states_;
  std::vector<std::pair<const Image*, std::function<void()>>> producers_;
};

}  // namespace lll
