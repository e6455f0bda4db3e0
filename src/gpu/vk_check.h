#pragma once
// VK_CHECK is always on: a failed Vulkan call throws with the expression, file, line and result.
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace lll {

const char* vkResultName(VkResult result);

class VulkanError : public std::runtime_error {
 public:
  VulkanError(const std::string& message, VkResult result) : std::runtime_error(message), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

[[noreturn]] void throwVulkanError(const char* expression, const char* file, int line, VkResult result);

}  // namespace lll

#define VK_CHECK(expression)                                                      \
  do {                                                                            \
    VkResult vk_check_result_ = (expression);                                     \
    if (vk_check_result_ != VK_SUCCESS)                                           \
      ::lll::throwVulkanError(#expression, __FILE__, __LINE__, vk_check_result_); \
  } while (0)
