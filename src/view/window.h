#pragma once
// The viewer's window: GLFW (no client API), a Vulkan surface and swapchain, and one present per
// frame that copies the renderer's display image to the swapchain image and draws Dear ImGui over
// it. Resizes and out-of-date swapchains are rebuilt; a minimised window presents nothing.
#include <vulkan/vulkan.h>

#include <functional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace lll {
class Context;
class Image;
}  // namespace lll

namespace lll::view {

// Starts GLFW once per process; throws InputError naming the display when there is none.
void initGlfw();
// The instance extensions a window surface needs (after initGlfw()).
std::vector<std::string> surfaceInstanceExtensions();

class Window {
 public:
  Window(const std::string& title, uint32_t width, uint32_t height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  // Creates the surface and swapchain on `context`'s device; throws InputError when its queue
  // cannot present to this window.
  void attach(Context& context);
  bool shouldClose() const;
  // The framebuffer's size in pixels (0 x 0 while minimised).
  void framebufferSize(uint32_t& width, uint32_t& height) const;
  void resize(uint32_t width, uint32_t height);  // asks the window system for a new size
  VkRenderPass renderPass() const { return renderPass_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }

  // Copies `source` (in `sourceLayout`, last written by a compute shader or read by a copy) to the
  // next swapchain image, scaled to fit, then runs `overlay` inside the render pass (ImGui) and
  // presents. Returns false when nothing was presented (minimised, or the swapchain was rebuilt).
  bool present(const Image& source, VkImageLayout sourceLayout,
               const std::function<void(VkCommandBuffer)>& overlay);

 private:
  void createSwapchain();
  void destroySwapchain();

  GLFWwindow* window_ = nullptr;
  Context* context_ = nullptr;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::vector<VkSemaphore> renderDone_;  // one per swapchain image: the present waits on it
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  VkFence frameDone_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  bool rebuild_ = false;
};

}  // namespace lll::view
