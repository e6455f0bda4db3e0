#include "particles/bitonic_sort.h"

#include <algorithm>
#include <bit>

#include "gpu/context.h"
#include "shared/particle_types.h"

namespace lll {

namespace {

// Largest group size worth having: 1,024-pair blocks (8 KiB of shared memory) already leave the
// global steps a small share of a 2^20 sort; the device's limits may ask for less.
constexpr uint32_t kPreferredThreads = 512;

uint32_t chooseThreads(const VkPhysicalDeviceLimits& limits) {
  uint32_t threads =
      std::min({kPreferredThreads, limits.maxComputeWorkGroupInvocations, limits.maxComputeWorkGroupSize[0],
                limits.maxComputeSharedMemorySize / uint32_t(2 * sizeof(uint32_t) * 2)});
  return std::bit_floor(std::max(threads, 1u));
}

void computeToCompute(VkCommandBuffer cmd) {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

}  // namespace

BitonicSort::BitonicSort(Context& context, uint32_t count)
    : context_(context),
      threads_(chooseThreads(context.properties().limits)),
      padded_(std::max(std::bit_ceil(std::max(count, 1u)), 2 * threads_)),
      layout_(context, {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT}},
              sizeof(gpu::SortPush), VK_SHADER_STAGE_COMPUTE_BIT) {
  sortBlocks_ = Pipeline(context, layout_, "particles/sort_local.comp", {threads_, 0});
  mergeInBlocks_ = Pipeline(context, layout_, "particles/sort_local.comp", {threads_, 1});
  mergeStep_ = Pipeline(context, layout_, "particles/sort_global.comp", {threads_});
}

void BitonicSort::record(VkCommandBuffer cmd, const Buffer& pairs) const {
  const uint32_t block = 2 * threads_;
  const uint32_t blocks = padded_ / block;
  const uint32_t pairGroups = padded_ / 2 / threads_;
  auto dispatch = [&](const Pipeline& pipeline, uint32_t k, uint32_t j, uint32_t groups) {
    pipeline.bind(cmd);
    DescriptorWriter()
        .storage(0, pairs.handle())
        .push(context_, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_);
    const gpu::SortPush push{glm::uvec4(k, j, padded_, 0)};
    vkCmdPushConstants(cmd, layout_.handle(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, groups, 1, 1);
  };
  dispatch(sortBlocks_, 0, 0, blocks);
  for (uint32_t k = 2 * block; k <= padded_; k *= 2) {
    for (uint32_t j = k / 2; j >= block; j /= 2) {
      computeToCompute(cmd);
      dispatch(mergeStep_, k, j, pairGroups);
    }
    computeToCompute(cmd);
    dispatch(mergeInBlocks_, k, 0, blocks);
  }
}

}  // namespace lll
