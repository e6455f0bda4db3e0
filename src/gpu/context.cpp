#include "gpu/context.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>

#include "core/errors.h"
#include "gpu/vk_check.h"

namespace lll {

const char* vkResultName(VkResult result) {
  switch (result) {
#define LLL_RESULT(name) \
  case name:             \
    return #name;
    LLL_RESULT(VK_SUCCESS)
    LLL_RESULT(VK_NOT_READY)
    LLL_RESULT(VK_TIMEOUT)
    LLL_RESULT(VK_INCOMPLETE)
    LLL_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    LLL_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    LLL_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    LLL_RESULT(VK_ERROR_DEVICE_LOST)
    LLL_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    LLL_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    LLL_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    LLL_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    LLL_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    LLL_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    LLL_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    LLL_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    LLL_RESULT(VK_SUBOPTIMAL_KHR)
    LLL_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
    LLL_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    LLL_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
#undef LLL_RESULT
    default:
      return "VK_ERROR_(unknown)";
  }
}

void throwVulkanError(const char* expression, const char* file, int line, VkResult result) {
  throw VulkanError(fmt::format("{} failed with {} at {}:{}", expression, vkResultName(result), file, line),
                    result);
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string deviceTypeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

// Lower is preferred: a real GPU before a software rasterizer.
int deviceRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 4;
    default:
      return 3;
  }
}

bool hasExtension(VkPhysicalDevice device, const char* name) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

int graphicsComputeQueue(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[i].queueFlags & need) == need) return int(i);
  }
  return -1;
}

DeviceInfo describe(VkPhysicalDevice device, uint32_t index) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(device, &properties);
  const VkPhysicalDeviceProperties& p = properties.properties;
  DeviceInfo info;
  info.index = index;
  info.name = p.deviceName;
  info.type = deviceTypeName(p.deviceType);
  info.driver = fmt::format("{} {}", driver.driverName, driver.driverInfo);
  info.apiVersion = fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(p.apiVersion),
                                VK_API_VERSION_MINOR(p.apiVersion), VK_API_VERSION_PATCH(p.apiVersion));

  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f13};
  if (p.apiVersion >= VK_API_VERSION_1_3) vkGetPhysicalDeviceFeatures2(device, &features);
  if (p.apiVersion < VK_API_VERSION_1_3)
    info.whyUnusable = "needs Vulkan 1.3";
  else if (graphicsComputeQueue(device) < 0)
    info.whyUnusable = "no graphics+compute queue";
  else if (!f13.dynamicRendering || !f13.synchronization2 || !f13.maintenance4)
    info.whyUnusable = "no dynamicRendering/synchronization2/maintenance4";
  else if (!features.features.fragmentStoresAndAtomics)
    info.whyUnusable = "no fragmentStoresAndAtomics";
  else if (!hasExtension(device, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
    info.whyUnusable = "no VK_KHR_push_descriptor";
  info.usable = info.whyUnusable.empty();
  return info;
}

bool hasInstanceExtension(const char* layer, const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(layer, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data());
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// What the validation layer checks beyond its defaults: synchronization always (hazards between
// passes are the bugs lavapipe's serial execution hides), GPU-assisted validation on request.
struct ValidationFeatures {
  std::vector<VkValidationFeatureEnableEXT> enabled;
  VkValidationFeaturesEXT info{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
};

VkInstance createBareInstance(bool validation, bool debugUtils, const ValidationFeatures* features = nullptr,
                              const std::vector<std::string>& wanted = {}) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "lll";
  app.apiVersion = VK_API_VERSION_1_3;
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (validation) layers.push_back(kValidationLayer);
  if (debugUtils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  for (const std::string& name : wanted) {
    if (!hasInstanceExtension(nullptr, name.c_str()))
      throw InputError(
          fmt::format("the Vulkan loader lacks the instance extension {}, which a window needs", name));
    extensions.push_back(name.c_str());
  }
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  if (features != nullptr) {
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    info.pNext = &features->info;
  }
  info.pApplicationInfo = &app;
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  const VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw InputError(
        "no Vulkan device: the Vulkan loader found no driver. Install a driver (on Debian: "
        "apt-get install mesa-vulkan-drivers for the CPU device lavapipe) or check VK_DRIVER_FILES.");
  VK_CHECK(result);
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

}  // namespace

std::vector<DeviceInfo> listDevices() {
  VkInstance instance = createBareInstance(false, false);
  std::vector<DeviceInfo> infos;
  const auto devices = physicalDevices(instance);
  for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
  vkDestroyInstance(instance, nullptr);
  return infos;
}

Context::Context(const ContextOptions& options) {
  createInstance(options);
  pickPhysicalDevice(options.device);
  createDevice(options.swapchain);
  if (!options.quiet)
    fmt::print(stderr, "lll: device {} ({}, {}, Vulkan {})\n", info_.name, info_.type, info_.driver,
               info_.apiVersion);
}

Context::~Context() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, commandPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

namespace {

// Mesa 22.3's SPIR-V front end (lavapipe, Debian 12) warns, through the debug messenger, about the
// Invariant decoration glslang puts on gl_PerVertex's gl_Position for `invariant gl_Position`
// (common/mesh.vert), which SPIR-V allows on members of a block. The warning is about the
// driver's parser, not about lll's use of Vulkan, so it is not recorded.
bool isKnownDriverNoise(const char* message) {
  return message != nullptr && std::strstr(message, "SPIR-V WARNING") != nullptr &&
         std::strstr(message, "Decoration not allowed on struct members: SpvDecorationInvariant") != nullptr;
}

}  // namespace

VKAPI_ATTR VkBool32 VKAPI_CALL Context::onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                            VkDebugUtilsMessageTypeFlagsEXT,
                                                            const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                            void* user) {
  auto* self = static_cast<Context*>(user);
  if (isKnownDriverNoise(data->pMessage)) return VK_FALSE;
  const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  std::string message = fmt::format("validation {}: {}", level, data->pMessage ? data->pMessage : "");
  fmt::print(stderr, "lll: {}\n", message);
  std::lock_guard lock(self->messagesMutex_);
  self->messages_.push_back(std::move(message));
  return VK_FALSE;
}

void Context::createInstance(const ContextOptions& options) {
  const bool validation = options.validation;
  validation_ = validation;
  if (validation) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    const bool found = std::any_of(layers.begin(), layers.end(), [](const VkLayerProperties& l) {
      return std::strcmp(l.layerName, kValidationLayer) == 0;
    });
    if (!found)
      throw InputError(
          "--validate needs the Khronos validation layer, which is not installed "
          "(on Debian: apt-get install vulkan-validationlayers)");
  }
  if (!validation) {
    instance_ = createBareInstance(false, false, nullptr, options.instanceExtensions);
    return;
  }
  if (!hasInstanceExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME))
    throw InputError(
        "--validate: the installed validation layer lacks " VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME
        ", which synchronization validation needs; update vulkan-validationlayers");
  ValidationFeatures features;
  features.enabled.push_back(VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT);
  if (options.gpuAssisted) {
    features.enabled.push_back(VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT);
    features.enabled.push_back(VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_RESERVE_BINDING_SLOT_EXT);
  }
  features.info.enabledValidationFeatureCount = uint32_t(features.enabled.size());
  features.info.pEnabledValidationFeatures = features.enabled.data();
  instance_ = createBareInstance(true, true, &features, options.instanceExtensions);
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType =
      VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT;
  info.pfnUserCallback = &Context::onValidationMessage;
  info.pUserData = this;
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
  VK_CHECK(create(instance_, &info, nullptr, &messenger_));
}

void Context::pickPhysicalDevice(const std::string& selector) {
  const auto devices = physicalDevices(instance_);
  std::vector<DeviceInfo> infos;
  for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
  std::string listing;
  for (const DeviceInfo& d : infos)
    listing += fmt::format("\n  {}: {} ({}){}", d.index, d.name, d.type,
                           d.usable ? "" : " unusable: " + d.whyUnusable);
  if (devices.empty())
    throw InputError(
        "no Vulkan device: the loader reports none (on Debian: apt-get install mesa-vulkan-drivers)");

  int chosen = -1;
  if (!selector.empty() && std::all_of(selector.begin(), selector.end(), ::isdigit)) {
    // Digits only, but maybe more than fit: an index that does not parse is no device's.
    size_t index = infos.size();
    std::from_chars(selector.data(), selector.data() + selector.size(), index);
    if (index >= infos.size() || !infos[index].usable)
      throw InputError(
          fmt::format("--device {}: no usable device with that index; devices:{}", selector, listing));
    chosen = int(index);
  } else if (selector == "auto" || selector == "gpu" || selector == "cpu") {
    int bestRank = 1 << 30;
    for (const DeviceInfo& d : infos) {
      if (!d.usable) continue;
      VkPhysicalDeviceProperties p;
      vkGetPhysicalDeviceProperties(devices[d.index], &p);
      const bool isCpu = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
      if ((selector == "gpu" && isCpu) || (selector == "cpu" && !isCpu)) continue;
      if (deviceRank(p.deviceType) < bestRank) {
        bestRank = deviceRank(p.deviceType);
        chosen = int(d.index);
      }
    }
    if (chosen < 0)
      throw InputError(fmt::format("no Vulkan device for --device {}; devices:{}", selector, listing));
  } else {
    throw InputError(fmt::format("--device {}: expected auto, gpu, cpu or a device index", selector));
  }
  physical_ = devices[size_t(chosen)];
  info_ = infos[size_t(chosen)];
  vkGetPhysicalDeviceProperties(physical_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  queueFamily_ = uint32_t(graphicsComputeQueue(physical_));
}

void Context::createDevice(bool swapchain) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
  timestampValidBits_ = families[queueFamily_].timestampValidBits;
  timestampPeriodNs_ = timestampValidBits_ ? properties_.limits.timestampPeriod : 0.0;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkPhysicalDeviceFeatures supported{};
  vkGetPhysicalDeviceFeatures(physical_, &supported);
  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  f13.dynamicRendering = VK_TRUE;
  f13.synchronization2 = VK_TRUE;
  f13.maintenance4 = VK_TRUE;  // glslc's SPIR-V 1.6 declares workgroup sizes with LocalSizeId
  VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &f13};
  // The visibility buffer (render/visibility.h) draws with gl_DrawID/gl_BaseInstance in indirect
  // multi-draws and writes gl_PrimitiveID from its fragment shader (Geometry capability).
  VkPhysicalDeviceVulkan12Features supported12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceVulkan11Features supported11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES,
                                               &supported12};
  VkPhysicalDeviceFeatures2 supported2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported11};
  vkGetPhysicalDeviceFeatures2(physical_, &supported2);
  visibilityBuffer_ = supported11.shaderDrawParameters && supported.multiDrawIndirect &&
                      supported.drawIndirectFirstInstance && supported.geometryShader;
  VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &f12};
  f11.shaderDrawParameters = visibilityBuffer_;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f11};
  features.features.multiDrawIndirect = visibilityBuffer_;
  features.features.drawIndirectFirstInstance = visibilityBuffer_;
  features.features.geometryShader = visibilityBuffer_;
  features.features.fragmentStoresAndAtomics = VK_TRUE;
  // The compute rasterizer (render/compute_raster.h): 64-bit atomic max of (depth, id) per pixel.
  computeRaster_ = supported.shaderInt64 && supported12.shaderBufferInt64Atomics;
  features.features.shaderInt64 = computeRaster_;
  f12.shaderBufferInt64Atomics = computeRaster_;
  features.features.samplerAnisotropy = supported.samplerAnisotropy;
  features.features.independentBlend = supported.independentBlend;
  features.features.depthClamp = supported.depthClamp;  // light volumes must not lose far faces
  features.features.pipelineStatisticsQuery = supported.pipelineStatisticsQuery;
  pipelineStatistics_ = supported.pipelineStatisticsQuery == VK_TRUE;
  // The visibility buffer's material textures: a workgroup-uniform index into the texture table
  // where the device has the first, any index where it has the second (common/visibility_surface.glsl).
  features.features.shaderSampledImageArrayDynamicIndexing = supported.shaderSampledImageArrayDynamicIndexing;
  float16_ = supported12.shaderFloat16 == VK_TRUE;
  f12.shaderFloat16 = supported12.shaderFloat16;
  nonUniformTextures_ = supported12.shaderSampledImageArrayNonUniformIndexing == VK_TRUE;
  f12.shaderSampledImageArrayNonUniformIndexing = supported12.shaderSampledImageArrayNonUniformIndexing;

  std::vector<const char*> extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  // A diagnostic for measurement runs (bench/README.md): the driver's statistics of each compute
  // pipeline, where it offers them.
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executableInfo{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  if (std::getenv("LLL_SHADER_STATS") &&
      hasExtension(physical_, VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
    executableInfo.pipelineExecutableInfo = VK_TRUE;
    executableInfo.pNext = f13.pNext;
    f13.pNext = &executableInfo;
    extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    shaderStatistics_ = true;
  }
  if (swapchain) {
    if (!hasExtension(physical_, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
      throw InputError(fmt::format("device {} cannot present to a window (no {})", info_.name,
                                   VK_KHR_SWAPCHAIN_EXTENSION_NAME));
    extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  }
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(physical_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  if (shaderStatistics_) {
    getPipelineExecutableProperties = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
        vkGetDeviceProcAddr(device_, "vkGetPipelineExecutablePropertiesKHR"));
    getPipelineExecutableStatistics = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
        vkGetDeviceProcAddr(device_, "vkGetPipelineExecutableStatisticsKHR"));
    shaderStatistics_ = getPipelineExecutableProperties && getPipelineExecutableStatistics;
  }

  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = queueFamily_;
  VK_CHECK(vkCreateCommandPool(device_, &poolInfo, nullptr, &commandPool_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &fence_));
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                 VkMemoryPropertyFlags preferred) const {
  for (int pass = 0; pass < 2; ++pass) {
    const VkMemoryPropertyFlags want = pass == 0 ? required | preferred : required;
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & want) == want) return i;
    }
  }
  throw std::runtime_error("no Vulkan memory type with the required properties");
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = commandPool_;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(device_, &allocInfo, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkResetFences(device_, 1, &fence_));
  VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
  VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
  vkFreeCommandBuffers(device_, commandPool_, 1, &cmd);
}

std::vector<std::string> Context::validationMessages() const {
  std::lock_guard lock(messagesMutex_);
  return messages_;
}

}  // namespace lll
