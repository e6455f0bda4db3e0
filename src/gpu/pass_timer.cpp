#include "gpu/pass_timer.h"

#include <stdexcept>

#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace lll {

PassTimer::PassTimer(Context& context) : context_(context) {
  if (context.timestampPeriodNs() <= 0.0) return;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = kMaxPasses * 2;
  VK_CHECK(vkCreateQueryPool(context.device(), &info, nullptr, &pool_));
}

PassTimer::~PassTimer() {
  if (pool_) vkDestroyQueryPool(context_.device(), pool_, nullptr);
}

void PassTimer::reset(VkCommandBuffer cmd) {
  names_.clear();
  open_ = 0;
  if (pool_) vkCmdResetQueryPool(cmd, pool_, 0, kMaxPasses * 2);
}

void PassTimer::begin(VkCommandBuffer cmd, std::string name) {
  if (names_.size() >= kMaxPasses)
    throw std::logic_error("PassTimer: more than kMaxPasses passes in one frame");
  if (open_) throw std::logic_error("PassTimer: passes must not nest (" + name + ")");
  open_ = 1;
  if (pool_)
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, pool_, uint32_t(names_.size() * 2));
  names_.push_back(std::move(name));
}

void PassTimer::end(VkCommandBuffer cmd) {
  open_ = 0;
  if (pool_)
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, pool_, uint32_t(names_.size() * 2 - 1));
}

std::vector<PassTime> PassTimer::read() {
  std::vector<PassTime> times;
  if (names_.empty()) return times;
  std::vector<uint64_t> ticks(names_.size() * 2, 0);
  if (pool_) {
    VK_CHECK(vkGetQueryPoolResults(context_.device(), pool_, 0, uint32_t(ticks.size()), ticks.size() * 8,
                                   ticks.data(), 8, VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  }
  const uint64_t mask =
      context_.timestampValidBits() >= 64 ? ~0ull : ((1ull << context_.timestampValidBits()) - 1);
  const double msPerTick = context_.timestampPeriodNs() * 1e-6;
  for (size_t i = 0; i < names_.size(); ++i) {
    const uint64_t delta = (ticks[2 * i + 1] - ticks[2 * i]) & mask;
    times.push_back({names_[i], double(delta) * msPerTick});
  }
  const uint64_t frame = (ticks.back() - ticks.front()) & mask;
  times.push_back({"frame", double(frame) * msPerTick});
  return times;
}

}  // namespace lll
