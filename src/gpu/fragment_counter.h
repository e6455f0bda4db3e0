#pragma once
// Counts the fragment shader invocations of the draws between begin() and end(): a pipeline
// statistics query. Techniques use it to report pixel overdraw (fragments per pixel) of a pass,
// e.g. deferred's light volumes. Where the device lacks pipelineStatisticsQuery it counts nothing
// and available() is false.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>

namespace lll {

class Context;

class FragmentCounter {
 public:
  FragmentCounter() = default;
  explicit FragmentCounter(Context& context);
  ~FragmentCounter();
  FragmentCounter(FragmentCounter&& other) noexcept;
  FragmentCounter& operator=(FragmentCounter&& other) noexcept;

  bool available() const { return pool_ != VK_NULL_HANDLE; }
  // Outside a render pass: resets the query for this frame.
  void reset(VkCommandBuffer cmd);
  void begin(VkCommandBuffer cmd);
  void end(VkCommandBuffer cmd);
  // After the frame's submission completed; nullopt when unavailable or never begun.
  std::optional<uint64_t> read();

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  bool recorded_ = false;
};

}  // namespace lll
