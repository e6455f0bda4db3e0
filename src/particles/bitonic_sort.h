#pragma once
// Sorts (key, value) pairs of 32-bit words on the GPU, ascending by key then by value: a bitonic
// sorting network in compute. Each block (2,048 pairs where shared memory allows) is sorted in
// shared memory in one dispatch; each larger merge takes its compare distances down to the block
// size up to four at a time (one dispatch each, the elements they compare held in registers), then
// one shared-memory dispatch for the rest. 2^20 pairs in blocks of 2,048: 25 dispatches (one step a
// dispatch in blocks of 1,024 took 66).
// A network, not a radix sort: no atomics and no subgroup operations (lavapipe's subgroups are 8
// wide, NVIDIA's 32), so the order is the same on every device, ties included.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "gpu/pipeline.h"
#include "gpu/resources.h"

namespace lll {

class Context;

class BitonicSort {
 public:
  // Sorts arrays of `count` pairs, padded to paddedCount().
  BitonicSort(Context& context, uint32_t count);

  // A power of two, at least one block: the pairs the sorted buffer must hold. Callers fill the
  // padding with keys that sort after every real one.
  uint32_t paddedCount() const { return padded_; }

  // Records the sort of the first paddedCount() pairs of `pairs`. The caller makes earlier writes
  // visible to compute shaders before, and the sorted pairs visible to their readers after.
  void record(VkCommandBuffer cmd, const Buffer& pairs) const;

 private:
  // Global compare distances one dispatch takes at most (2^4 = 16 pairs in registers an invocation).
  static constexpr uint32_t kMaxFusedSteps = 4;

  Context& context_;
  uint32_t block_ = 0;    // pairs a shared-memory block holds
  uint32_t threads_ = 0;  // a workgroup's invocations
  uint32_t padded_ = 0;
  PipelineLayout layout_;
  Pipeline sortBlocks_;
  Pipeline mergeInBlocks_;
  Pipeline mergeSteps_[kMaxFusedSteps];  // 1 to kMaxFusedSteps global steps a dispatch
};

}  // namespace lll
