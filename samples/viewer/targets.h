// Where frames go: an offscreen image read back to the host (headless), or
// a window's swapchain. Both use 8-bit UNORM colour, so a frame has the same
// bytes in either.
#pragma once

#include "renderer.h"
#include "vulkan_context.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace viewer {

constexpr VkFormat kOffscreenFormat = VK_FORMAT_R8G8B8A8_UNORM;

// The multisampled colour and the depth attachment a framebuffer shares
// with its final image.
class Attachments {
 public:
  Attachments(VulkanContext& vk, VkFormat format, VkExtent2D extent, VkSampleCountFlagBits samples);
  ~Attachments();
  Attachments(const Attachments&) = delete;
  Attachments& operator=(const Attachments&) = delete;
  VkFramebuffer framebuffer(VkRenderPass pass, VkImageView final_view, VkExtent2D extent);

 private:
  VulkanContext& vk_;
  Image msaa_, depth_;
  std::vector<VkFramebuffer> framebuffers_;
};

class OffscreenTarget {
 public:
  OffscreenTarget(VulkanContext& vk, const Renderer& renderer, VkExtent2D extent);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;
  VkFramebuffer framebuffer() const { return framebuffer_; }
  VkExtent2D extent() const { return extent_; }
  // Records the copy of the rendered image into the host buffer.
  void record_readback(VkCommandBuffer cmd);
  // After the frame's fence: the image as RGB rows, top first.
  std::vector<uint8_t> rgb() const;

 private:
  VulkanContext& vk_;
  VkExtent2D extent_;
  Image image_;
  Attachments attachments_;
  VkFramebuffer framebuffer_;
  Buffer readback_;
};

class SwapchainTarget {
 public:
  // Prefers B8G8R8A8_UNORM (what the offscreen image holds, byte for byte)
  // and FIFO presentation.
  SwapchainTarget(VulkanContext& vk, VkSurfaceKHR surface, VkExtent2D extent);
  ~SwapchainTarget();
  SwapchainTarget(const SwapchainTarget&) = delete;
  SwapchainTarget& operator=(const SwapchainTarget&) = delete;
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  // Builds the swapchain (again, after a resize) for the renderer's pass.
  void create(const Renderer& renderer, VkExtent2D extent);
  // Acquires the next image; false when the swapchain must be re-created.
  bool acquire(VkFramebuffer* fb);
  VkSemaphore acquired() const { return acquired_; }
  VkSemaphore rendered() const { return rendered_[index_]; }
  // Presents the acquired image; false when the swapchain must be re-created.
  bool present();

 private:
  void destroy_swapchain();
  VulkanContext& vk_;
  VkSurfaceKHR surface_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkColorSpaceKHR color_space_ = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  VkExtent2D extent_{};
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  std::vector<VkImageView> views_;
  std::vector<VkFramebuffer> framebuffers_;
  std::unique_ptr<Attachments> attachments_;
  VkSemaphore acquired_ = VK_NULL_HANDLE;
  std::vector<VkSemaphore> rendered_;  // one per image: reused only once that image is acquired again
  uint32_t index_ = 0;
};

}  // namespace viewer
