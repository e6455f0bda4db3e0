#pragma once
// Move-only RAII buffers and images. Each owns a dedicated VkDeviceMemory: lll allocates a few
// dozen long-lived resources per renderer, far below maxMemoryAllocationCount, and Debian 12 ships
// no Vulkan memory allocator library, so a sub-allocator would be code without a payoff.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace lll {

class Context;

enum class MemoryUse {
  Device,    // GPU only; filled by uploads or passes
  Upload,    // host-visible, mapped: written by the CPU every frame
  Readback,  // host-visible, mapped: read by the CPU after a frame
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, std::string name = {});
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
  VkDescriptorBufferInfo descriptor() const { return {buffer_, 0, VK_WHOLE_SIZE}; }

  // Copies bytes into the buffer: directly when mapped, else through a staging buffer.
  void upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  // Copies the first `bytes` of `source` (a buffer the CPU filled) to `offset` in this one, on the
  // GPU, and waits for the copy.
  void copyFrom(const Buffer& source, VkDeviceSize bytes, VkDeviceSize offset = 0);
  template <typename T>
  void upload(std::span<const T> items) {
    upload(items.data(), items.size_bytes());
  }

 private:
  void release();
  Context* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

class Image {
 public:
  Image() = default;
  Image(Context& context, uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
        std::string name = {}, uint32_t mipLevels = 1);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  VkImageAspectFlags aspect() const;
  // Every mip level of the image's one layer, its whole aspect.
  VkImageSubresourceRange subresourceRange() const { return {aspect(), 0, mipLevels_, 0, 1}; }
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

  // Records a layout transition with a full barrier between the given stages/accesses.
  void transition(VkCommandBuffer cmd, VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                  VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) const;

 private:
  void release();
  Context* context_ = nullptr;
  VkImage image_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  uint32_t width_ = 0;
  uint32_t height_ = 0;
  uint32_t mipLevels_ = 1;
};

// A global memory barrier: what a pass wrote becomes visible to what the next pass reads.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

// The first `bytes` of a device buffer, copied back after everything submitted before has finished
// writing it (a barrier from every command's writes, then one to the host: a fence alone does not
// make another submission's writes visible to the copy).
std::vector<uint8_t> readBack(Context& context, const Buffer& buffer, VkDeviceSize bytes);
// Uploads `bytes` of tightly packed texels to mip level 0 of `image` (its contents before are
// dropped) through a staging buffer, leaving it in TRANSFER_DST_OPTIMAL, then records `after` in the
// same submission (mip levels, the move to shader reads) and waits for it.
void uploadImage(Context& context, const Image& image, const void* texels, VkDeviceSize bytes,
                 const std::function<void(VkCommandBuffer)>& after);
// A nearest-filtering, clamp-to-edge sampler (for texel-exact reads of depth and G-buffers); the
// caller destroys it.
VkSampler createNearestClampSampler(Context& context);

// The whole buffer as 32-bit words (for tests and tools reading a technique's lists).
std::vector<uint32_t> readBackWords(Context& context, const Buffer& buffer);

}  // namespace lll
