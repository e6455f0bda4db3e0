#include "particles/bitonic_sort.h"

#include <algorithm>
#include <bit>
#include <vector>

#include "gpu/context.h"
#include "shared/particle_types.h"

namespace lll {

namespace {

// Shared-memory block: 2,048 pairs (16 KiB) a workgroup of 512. On the H200 (bench/README.md,
// 2026-12-03 seventh), blocks of 1,024 / 2,048 / 4,096 pairs with four global steps a dispatch sorted
// 65,536 slots in 0.101 / 0.106 / 0.126 ms and 2^20 in 0.438 / 0.417 / 0.435 (larger blocks leave
// too few workgroups for the sort from scratch). The device's limits may ask for less.
constexpr uint32_t kPreferredBlock = 2048;
constexpr uint32_t kPreferredThreads = 512;

uint32_t chooseBlock(const VkPhysicalDeviceLimits& limits) {
  const uint32_t block =
      std::min(kPreferredBlock, limits.maxComputeSharedMemorySize / uint32_t(2 * sizeof(uint32_t)));
  return std::bit_floor(std::max(block, 2u));
}

uint32_t chooseThreads(const VkPhysicalDeviceLimits& limits, uint32_t block) {
  const uint32_t threads = std::min({kPreferredThreads, block / 2, limits.maxComputeWorkGroupInvocations,
                                     limits.maxComputeWorkGroupSize[0]});
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
      block_(chooseBlock(context.properties().limits)),
      threads_(chooseThreads(context.properties().limits, block_)),
      padded_(std::max(std::bit_ceil(std::max(count, 1u)), block_)),
      layout_(context, {"particles/sort_local.comp", "particles/sort_global.comp"}) {
  sortBlocks_ = Pipeline(context, layout_, "particles/sort_local.comp", {threads_, 0, block_});
  mergeInBlocks_ = Pipeline(context, layout_, "particles/sort_local.comp", {threads_, 1, block_});
  for (uint32_t steps = 1; steps <= kMaxFusedSteps; ++steps)
    mergeSteps_[steps - 1] =
        Pipeline(context, layout_, "particles/sort_global.comp", std::vector<uint32_t>{threads_, steps});
}

void BitonicSort::record(VkCommandBuffer cmd, const Buffer& pairs) const {
  const uint32_t blocks = padded_ / block_;
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
  for (uint32_t k = 2 * block_; k <= padded_; k *= 2) {
    // Distances k / 2 .. block_, up to kMaxFusedSteps a dispatch.
    for (uint32_t j = k / 2; j >= block_;) {
      const uint32_t steps =
          std::min(kMaxFusedSteps, uint32_t(std::countr_zero(j) - std::countr_zero(block_)) + 1);
      computeToCompute(cmd);
      dispatch(mergeSteps_[steps - 1], k, j, std::max((padded_ >> steps) / threads_, 1u));
      j >>= steps;
    }
    computeToCompute(cmd);
    dispatch(mergeInBlocks_, k, 0, blocks);
  }
}

}  // namespace lll
