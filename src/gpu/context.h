#pragma once
// The Vulkan instance, the chosen physical device, one graphics+compute queue, and the validation
// messenger. Devices are ranked discrete GPU first, CPU (lavapipe) last.
#include <vulkan/vulkan.h>

#include <functional>
#include <mutex>
#include <string>
#include <vector>

namespace lll {

// The stage of every compute pass's barriers.
inline constexpr VkPipelineStageFlags2 kCompute = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;

struct ContextOptions {
  std::string device = "auto";  // auto | gpu | cpu | INDEX (position in `lll devices`)
  bool validation = false;      // Khronos validation layers, synchronization validation included;
                                // every message is recorded
  bool gpuAssisted = false;     // with validation: GPU-assisted validation (out-of-bounds
                                // descriptor and buffer accesses inside shaders) as well
  bool quiet = false;           // do not print the chosen device
  // For a window (lll view): the instance extensions its surface needs (glfwGetRequiredInstanceExtensions)
  // and VK_KHR_swapchain on the device. Off-screen rendering needs neither.
  std::vector<std::string> instanceExtensions;
  bool swapchain = false;
};

struct DeviceInfo {
  uint32_t index = 0;
  std::string name;
  std::string type;  // discrete, integrated, virtual, cpu, other
  std::string driver;
  std::string apiVersion;
  bool usable = false;  // Vulkan 1.3 with a graphics+compute queue and the features lll needs
  std::string whyUnusable;
};

// Every Vulkan device on this machine, in enumeration order (for `lll devices` and --device INDEX).
std::vector<DeviceInfo> listDevices();

class Context {
 public:
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const DeviceInfo& info() const { return info_; }
  bool isCpuDevice() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  // Nanoseconds per timestamp tick; 0 when the queue has no timestamps.
  double timestampPeriodNs() const { return timestampPeriodNs_; }
  uint32_t timestampValidBits() const { return timestampValidBits_; }
  // pipelineStatisticsQuery is enabled (fragment counts for overdraw; see fragment_counter.h).
  bool pipelineStatistics() const { return pipelineStatistics_; }
  // shaderDrawParameters, multiDrawIndirect, drawIndirectFirstInstance and geometryShader are
  // enabled: what the visibility buffer's pass needs (render/visibility.h).
  bool visibilityBufferFeatures() const { return visibilityBuffer_; }
  // shaderInt64 and shaderBufferInt64Atomics, which the compute rasterizer needs.
  bool computeRasterFeatures() const { return computeRaster_; }
  // shaderSampledImageArrayNonUniformIndexing is enabled: a shader may index a sampler array with a
  // value that differs between invocations (the visibility buffer's surface rebuild).
  bool nonUniformTextureFeatures() const { return nonUniformTextures_; }
  // shaderFloat16 is enabled (the bench's half-precision ALU probe, bench/alu_probe.h).
  bool float16Features() const { return float16_; }
  // LLL_SHADER_STATS set and VK_KHR_pipeline_executable_properties there: each compute pipeline's
  // driver statistics (registers, shared memory, ...) are printed to stderr as it is made.
  bool shaderStatistics() const { return shaderStatistics_; }

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                          VkMemoryPropertyFlags preferred = 0) const;

  // Records commands into a fresh command buffer, submits them and waits for completion.
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

  // Validation messages (warnings and errors) seen since creation.
  std::vector<std::string> validationMessages() const;
  bool validationEnabled() const { return validation_; }

  PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;
  PFN_vkGetPipelineExecutablePropertiesKHR getPipelineExecutableProperties = nullptr;
  PFN_vkGetPipelineExecutableStatisticsKHR getPipelineExecutableStatistics = nullptr;

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                            VkDebugUtilsMessageTypeFlagsEXT types,
                                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                            void* user);
  void createInstance(const ContextOptions& options);
  void pickPhysicalDevice(const std::string& selector);
  void createDevice(bool swapchain);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool commandPool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  DeviceInfo info_;
  double timestampPeriodNs_ = 0.0;
  uint32_t timestampValidBits_ = 0;
  bool validation_ = false;
  bool pipelineStatistics_ = false;
  bool visibilityBuffer_ = false;
  bool computeRaster_ = false;
  bool nonUniformTextures_ = false;
  bool float16_ = false;
  bool shaderStatistics_ = false;
  mutable std::mutex messagesMutex_;
  std::vector<std::string> messages_;
};

}  // namespace lll
