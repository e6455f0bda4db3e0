#include "view/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "lll.h"  // the viewer uses the library's public API only

namespace lll::view {

namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

}  // namespace

void initGlfw() {
  static bool started = false;
  if (started) return;
  if (!glfwInit())
    throw InputError(fmt::format(
        "lll view: cannot open a window ({}); it needs a display: set DISPLAY (on a machine without one, run "
        "it under xvfb-run)",
        lastGlfwError()));
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw InputError("lll view: GLFW found no Vulkan loader able to create window surfaces");
  }
  started = true;
  std::atexit(glfwTerminate);
}

std::vector<std::string> surfaceInstanceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (names == nullptr) throw InputError(fmt::format("lll view: no window surfaces ({})", lastGlfwError()));
  return std::vector<std::string>(names, names + count);
}

Window::Window(const std::string& title, uint32_t width, uint32_t height) {
  initGlfw();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (window_ == nullptr)
    throw InputError(
        fmt::format("lll view: cannot create a {} x {} window ({})", width, height, lastGlfwError()));
}

Window::~Window() {
  if (context_) {
    VkDevice device = context_->device();
    vkDeviceWaitIdle(device);
    destroySwapchain();
    vkDestroyRenderPass(device, renderPass_, nullptr);
    vkDestroySemaphore(device, acquired_, nullptr);
    vkDestroyFence(device, frameDone_, nullptr);
    vkDestroyCommandPool(device, pool_, nullptr);
    vkDestroySurfaceKHR(context_->instance(), surface_, nullptr);
  }
  if (window_) glfwDestroyWindow(window_);
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(window_);
}

void Window::framebufferSize(uint32_t& width, uint32_t& height) const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  width = uint32_t(std::max(w, 0));
  height = uint32_t(std::max(h, 0));
}

void Window::resize(uint32_t width, uint32_t height) {
  glfwSetWindowSize(window_, int(width), int(height));
}

void Window::attach(Context& context) {
  context_ = &context;
  VK_CHECK(glfwCreateWindowSurface(context.instance(), window_, nullptr, &surface_));
  VkBool32 supported = VK_FALSE;
  VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(context.physicalDevice(), context.queueFamily(), surface_,
                                                &supported));
  if (!supported)
    throw InputError(fmt::format("lll view: device {} cannot present to this window from its graphics queue",
                                 context.info().name));
  // The display image is sRGB-encoded already: a UNORM swapchain shows its bytes as they are.
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice(), surface_, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(context.physicalDevice(), surface_, &count, formats.data()));
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM})
    for (const VkSurfaceFormatKHR& f : formats)
      if (format_ == VK_FORMAT_UNDEFINED && f.format == wanted) format_ = f.format;
  if (format_ == VK_FORMAT_UNDEFINED)
    throw InputError("lll view: the window offers no 8-bit UNORM swapchain format (B8G8R8A8 or R8G8B8A8)");

  VkDevice device = context.device();
  // Loaded after the copy of the frame (TRANSFER_DST), ImGui drawn over it, then presented.
  VkAttachmentDescription color{};
  color.format = format_;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  // The copy into the image happens before the pass loads it.
  VkSubpassDependency dependency{};
  dependency.srcSubpass = VK_SUBPASS_EXTERNAL;
  dependency.dstSubpass = 0;
  dependency.srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependency.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  dependency.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependency.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  passInfo.attachmentCount = 1;
  passInfo.pAttachments = &color;
  passInfo.subpassCount = 1;
  passInfo.pSubpasses = &subpass;
  passInfo.dependencyCount = 1;
  passInfo.pDependencies = &dependency;
  VK_CHECK(vkCreateRenderPass(device, &passInfo, nullptr, &renderPass_));

  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &acquired_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device, &fenceInfo, nullptr, &frameDone_));
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = context.queueFamily();
  VK_CHECK(vkCreateCommandPool(device, &poolInfo, nullptr, &pool_));
  VkCommandBufferAllocateInfo allocInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocInfo.commandPool = pool_;
  allocInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocInfo.commandBufferCount = 1;
  VK_CHECK(vkAllocateCommandBuffers(device, &allocInfo, &cmd_));
  createSwapchain();
}

void Window::createSwapchain() {
  VkPhysicalDevice physical = context_->physicalDevice();
  VkDevice device = context_->device();
  VkSurfaceCapabilitiesKHR caps{};
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps));
  uint32_t width = 0, height = 0;
  framebufferSize(width, height);
  if (caps.currentExtent.width != std::numeric_limits<uint32_t>::max()) {
    width = caps.currentExtent.width;
    height = caps.currentExtent.height;
  }
  extent_ = {std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width),
             std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  if (extent_.width == 0 || extent_.height == 0) return;  // minimised: nothing to present to
  if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
    throw InputError("lll view: the window's swapchain images cannot be copied to (no TRANSFER_DST usage)");
  uint32_t images = std::max(caps.minImageCount, 2u);
  if (caps.maxImageCount > 0) images = std::min(images, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = images;
  info.imageFormat = format_;
  info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha =
      (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
          ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
          : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported; the frame itself is the bottleneck
  info.clipped = VK_TRUE;
  VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_));
  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
    views_.push_back(view);
    VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fbInfo.renderPass = renderPass_;
    fbInfo.attachmentCount = 1;
    fbInfo.pAttachments = &view;
    fbInfo.width = extent_.width;
    fbInfo.height = extent_.height;
    fbInfo.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(device, &fbInfo, nullptr, &framebuffer));
    framebuffers_.push_back(framebuffer);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(device, &semaphoreInfo, nullptr, &semaphore));
    renderDone_.push_back(semaphore);
  }
}

void Window::destroySwapchain() {
  VkDevice device = context_->device();
  for (VkFramebuffer f : framebuffers_) vkDestroyFramebuffer(device, f, nullptr);
  for (VkImageView v : views_) vkDestroyImageView(device, v, nullptr);
  for (VkSemaphore s : renderDone_) vkDestroySemaphore(device, s, nullptr);
  framebuffers_.clear();
  views_.clear();
  renderDone_.clear();
  images_.clear();
  if (swapchain_) vkDestroySwapchainKHR(device, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
}

bool Window::present(const Image& source, VkImageLayout sourceLayout,
                     const std::function<void(VkCommandBuffer)>& overlay) {
  VkDevice device = context_->device();
  uint32_t width = 0, height = 0;
  framebufferSize(width, height);
  if (rebuild_ || swapchain_ == VK_NULL_HANDLE || width != extent_.width || height != extent_.height) {
    vkDeviceWaitIdle(device);
    destroySwapchain();
    createSwapchain();
    rebuild_ = false;
    if (swapchain_ == VK_NULL_HANDLE) return false;
  }
  uint32_t index = 0;
  VkResult acquire = vkAcquireNextImageKHR(device, swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
  if (acquire == VK_ERROR_OUT_OF_DATE_KHR) {
    rebuild_ = true;
    return false;
  }
  if (acquire != VK_SUBOPTIMAL_KHR) VK_CHECK(acquire);

  VK_CHECK(vkResetCommandBuffer(cmd_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd_, &begin));
  // The frame's display image: from the renderer's last use to a copy source.
  VkImageMemoryBarrier2 barriers[2]{};
  barriers[0] = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  barriers[0].srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COPY_BIT;
  barriers[0].srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
  barriers[0].dstStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  barriers[0].dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
  barriers[0].oldLayout = sourceLayout;
  barriers[0].newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  barriers[0].srcQueueFamilyIndex = barriers[0].dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barriers[0].image = source.handle();
  barriers[0].subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  // The swapchain image: its old contents are not needed; the acquire semaphore's wait stage is the blit.
  barriers[1] = barriers[0];
  barriers[1].srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  barriers[1].srcAccessMask = 0;
  barriers[1].dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  barriers[1].oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  barriers[1].newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  barriers[1].image = images_[index];
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 2;
  dependency.pImageMemoryBarriers = barriers;
  vkCmdPipelineBarrier2(cmd_, &dependency);
  VkImageBlit blit{};
  blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(source.width()), int32_t(source.height()), 1};
  blit.dstSubresource = blit.srcSubresource;
  blit.dstOffsets[1] = {int32_t(extent_.width), int32_t(extent_.height), 1};
  const bool sameSize = source.width() == extent_.width && source.height() == extent_.height;
  vkCmdBlitImage(cmd_, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, images_[index],
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit,
                 sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
  // Back to the layout the renderer's next frame finds it in (its tonemap writes it as storage).
  VkImageMemoryBarrier2 back = barriers[0];
  back.srcStageMask = VK_PIPELINE_STAGE_2_BLIT_BIT;
  back.srcAccessMask = 0;
  back.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
  back.dstAccessMask = 0;
  back.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  back.newLayout = VK_IMAGE_LAYOUT_GENERAL;
  VkDependencyInfo backDependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  backDependency.imageMemoryBarrierCount = 1;
  backDependency.pImageMemoryBarriers = &back;
  vkCmdPipelineBarrier2(cmd_, &backDependency);

  VkRenderPassBeginInfo passBegin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  passBegin.renderPass = renderPass_;
  passBegin.framebuffer = framebuffers_[index];
  passBegin.renderArea.extent = extent_;
  vkCmdBeginRenderPass(cmd_, &passBegin, VK_SUBPASS_CONTENTS_INLINE);
  if (overlay) overlay(cmd_);
  vkCmdEndRenderPass(cmd_);
  VK_CHECK(vkEndCommandBuffer(cmd_));

  const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &acquired_;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &renderDone_[index];
  VK_CHECK(vkResetFences(device, 1, &frameDone_));
  VK_CHECK(vkQueueSubmit(context_->queue(), 1, &submit, frameDone_));
  VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  presentInfo.waitSemaphoreCount = 1;
  presentInfo.pWaitSemaphores = &renderDone_[index];
  presentInfo.swapchainCount = 1;
  presentInfo.pSwapchains = &swapchain_;
  presentInfo.pImageIndices = &index;
  const VkResult presented = vkQueuePresentKHR(context_->queue(), &presentInfo);
  // One frame in flight: the renderer records its next frame only after this one is done.
  VK_CHECK(vkWaitForFences(device, 1, &frameDone_, VK_TRUE, UINT64_MAX));
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR)
    rebuild_ = true;
  else
    VK_CHECK(presented);
  return true;
}

}  // namespace lll::view
