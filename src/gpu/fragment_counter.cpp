#include "gpu/fragment_counter.h"

#include <utility>

#include "gpu/context.h"
#include "gpu/vk_check.h"

namespace lll {

FragmentCounter::FragmentCounter(Context& context) : device_(context.device()) {
  if (!context.pipelineStatistics()) return;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
  info.queryCount = 1;
  info.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
  VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool_));
}

FragmentCounter::~FragmentCounter() {
  if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
}

FragmentCounter::FragmentCounter(FragmentCounter&& other) noexcept
    : device_(other.device_), pool_(std::exchange(other.pool_, VK_NULL_HANDLE)), recorded_(other.recorded_) {}

FragmentCounter& FragmentCounter::operator=(FragmentCounter&& other) noexcept {
  if (this != &other) {
    if (pool_) vkDestroyQueryPool(device_, pool_, nullptr);
    device_ = other.device_;
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    recorded_ = other.recorded_;
  }
  return *this;
}

void FragmentCounter::reset(VkCommandBuffer cmd) {
  recorded_ = false;
  if (pool_) vkCmdResetQueryPool(cmd, pool_, 0, 1);
}

void FragmentCounter::begin(VkCommandBuffer cmd) {
  if (pool_) vkCmdBeginQuery(cmd, pool_, 0, 0);
}

void FragmentCounter::end(VkCommandBuffer cmd) {
  if (!pool_) return;
  vkCmdEndQuery(cmd, pool_, 0);
  recorded_ = true;
}

std::optional<uint64_t> FragmentCounter::read() {
  if (!pool_ || !recorded_) return std::nullopt;
  uint64_t count = 0;
  VK_CHECK(vkGetQueryPoolResults(device_, pool_, 0, 1, sizeof(count), &count, sizeof(count),
                                 VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  return count;
}

}  // namespace lll
