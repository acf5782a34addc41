// The Vulkan instance (with the validation layer and its messenger when
// asked), the device and its one queue, buffers and images: what every
// part of the renderer shares.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace viewer {

// Anything Vulkan refused, with what was being done.
struct VulkanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void vk_check(VkResult r, const char* what);

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;  // host-visible and coherent: written directly
  VkDeviceSize size = 0;
};

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

class VulkanContext {
 public:
  // Instance extensions: the window system's (empty headless). Validation:
  // VK_LAYER_KHRONOS_validation with synchronisation validation and a
  // messenger that prints every warning and error and counts it.
  VulkanContext(const std::vector<const char*>& extensions, bool validation);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  // Picks the device: headless (surface null) the CPU one (lavapipe) if
  // there is one, else any; with a surface, one that can present to it,
  // a discrete or integrated GPU first. Needs Vulkan 1.1.
  void pick_device(VkSurfaceKHR surface, VkSampleCountFlagBits samples);

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return family_; }
  const std::string& device_name() const { return device_name_; }
  // Validation messages so far (0 without --validation).
  static int validation_messages();

  Buffer create_buffer(VkDeviceSize size, VkBufferUsageFlags usage);
  void destroy(Buffer& b);
  Image create_image(VkFormat format, VkExtent2D extent, VkSampleCountFlagBits samples,
                     VkImageUsageFlags usage, VkImageAspectFlags aspect);
  void destroy(Image& i);

  // One primary command buffer and its fence, for the frame.
  VkCommandBuffer begin_frame();
  // Submits the frame's commands (waiting for and signalling the given
  // semaphores, which may be null) and returns without waiting.
  void submit(VkSemaphore wait, VkPipelineStageFlags wait_stage, VkSemaphore signal);
  void wait_frame();

 private:
  uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags want, VkMemoryPropertyFlags fallback) const;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t family_ = 0;
  std::string device_name_;
  VkPhysicalDeviceMemoryProperties memory_{};
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  bool submitted_ = false;
};

}  // namespace viewer
