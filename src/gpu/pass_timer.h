#pragma once
// GPU timestamps around every named pass of a frame. The pass layer owns them: a pass is recorded
// between begin() and end(), and after the frame's fence the durations are read back in order.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace lll {

class Context;

struct PassTime {
  std::string name;
  double ms = 0.0;
};

class PassTimer {
 public:
  static constexpr uint32_t kMaxPasses = 64;

  explicit PassTimer(Context& context);
  ~PassTimer();
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  // Resets the query pool; call once at the start of each frame's command buffer.
  void reset(VkCommandBuffer cmd);
  void begin(VkCommandBuffer cmd, std::string name);
  void end(VkCommandBuffer cmd);
  // After the frame completed: each pass's GPU time, plus "frame" from the first begin to the last end.
  std::vector<PassTime> read();
  bool enabled() const { return pool_ != VK_NULL_HANDLE; }

 private:
  Context& context_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  std::vector<std::string> names_;
  uint32_t open_ = 0;
};

// Times one pass for the scope of a block: `ScopedPass pass(timer, cmd, "depth-prepass");`.
class ScopedPass {
 public:
  ScopedPass(PassTimer& timer, VkCommandBuffer cmd, std::string name) : timer_(timer), cmd_(cmd) {
    timer_.begin(cmd_, std::move(name));
  }
  ~ScopedPass() { timer_.end(cmd_); }
  ScopedPass(const ScopedPass&) = delete;
  ScopedPass& operator=(const ScopedPass&) = delete;

 private:
  PassTimer& timer_;
  VkCommandBuffer cmd_;
};

}  // namespace lll
