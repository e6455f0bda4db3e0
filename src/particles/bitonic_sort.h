#pragma once
// Sorts (key, value) pairs of 32-bit words on the GPU, ascending by key then by value: a bitonic
// sorting network in compute. Each block of 2 x workgroup-size pairs is sorted in shared memory in
// one dispatch; each larger merge takes one dispatch per compare distance down to the block size,
// then one shared-memory dispatch for the rest. 2^20 pairs with 512-thread groups: 66 dispatches.
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
  Context& context_;
  uint32_t threads_ = 0;
  uint32_t padded_ = 0;
  PipelineLayout layout_;
  Pipeline sortBlocks_;
  Pipeline mergeInBlocks_;
  Pipeline mergeStep_;
};

}  // namespace lll
