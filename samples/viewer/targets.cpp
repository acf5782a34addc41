#include "targets.h"

#include <algorithm>
#include <cstring>

namespace viewer {

Attachments::Attachments(VulkanContext& vk, VkFormat format, VkExtent2D extent, VkSampleCountFlagBits samples)
    : vk_(vk) {
  if (samples != VK_SAMPLE_COUNT_1_BIT)
    msaa_ = vk.create_image(format, extent, samples,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT);
  depth_ = vk.create_image(VK_FORMAT_D32_SFLOAT, extent, samples, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                           VK_IMAGE_ASPECT_DEPTH_BIT);
}

Attachments::~Attachments() {
  for (VkFramebuffer fb : framebuffers_) vkDestroyFramebuffer(vk_.device(), fb, nullptr);
  vk_.destroy(msaa_);
  vk_.destroy(depth_);
}

VkFramebuffer Attachments::framebuffer(VkRenderPass pass, VkImageView final_view, VkExtent2D extent) {
  VkImageView views[3];
  uint32_t n = 0;
  if (msaa_.view) {
    views[n++] = msaa_.view;
    views[n++] = depth_.view;
    views[n++] = final_view;
  } else {
    views[n++] = final_view;
    views[n++] = depth_.view;
  }
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = pass;
  info.attachmentCount = n;
  info.pAttachments = views;
  info.width = extent.width;
  info.height = extent.height;
  info.layers = 1;
  VkFramebuffer fb;
  vk_check(vkCreateFramebuffer(vk_.device(), &info, nullptr, &fb), "vkCreateFramebuffer");
  framebuffers_.push_back(fb);
  return fb;
}

OffscreenTarget::OffscreenTarget(VulkanContext& vk, const Renderer& renderer, VkExtent2D extent)
    : vk_(vk),
      extent_(extent),
      image_(vk.create_image(kOffscreenFormat, extent, VK_SAMPLE_COUNT_1_BIT,
                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT)),
      attachments_(vk, kOffscreenFormat, extent, renderer.samples()),
      framebuffer_(attachments_.framebuffer(renderer.render_pass(), image_.view, extent)),
      readback_(vk.create_buffer(VkDeviceSize{4} * extent.width * extent.height,
                                 VK_BUFFER_USAGE_TRANSFER_DST_BIT)) {}

OffscreenTarget::~OffscreenTarget() {
  vkDeviceWaitIdle(vk_.device());
  vk_.destroy(readback_);
  vk_.destroy(image_);
}

void OffscreenTarget::record_readback(VkCommandBuffer cmd) {
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {extent_.width, extent_.height, 1};
  vkCmdCopyImageToBuffer(cmd, image_.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.buffer, 1, &copy);
  VkBufferMemoryBarrier barrier{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.buffer = readback_.buffer;
  barrier.size = VK_WHOLE_SIZE;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr, 1,
                       &barrier, 0, nullptr);
}

std::vector<uint8_t> OffscreenTarget::rgb() const {
  const std::size_t n = std::size_t{extent_.width} * extent_.height;
  std::vector<uint8_t> out(3 * n);
  const uint8_t* in = static_cast<const uint8_t*>(readback_.mapped);
  for (std::size_t i = 0; i < n; ++i) std::memcpy(&out[3 * i], &in[4 * i], 3);
  return out;
}

SwapchainTarget::SwapchainTarget(VulkanContext& vk, VkSurfaceKHR surface, VkExtent2D extent)
    : vk_(vk), surface_(surface), extent_(extent) {
  uint32_t n = 0;
  vk_check(vkGetPhysicalDeviceSurfaceFormatsKHR(vk.physical(), surface, &n, nullptr),
           "vkGetPhysicalDeviceSurfaceFormatsKHR");
  std::vector<VkSurfaceFormatKHR> formats(n);
  vk_check(vkGetPhysicalDeviceSurfaceFormatsKHR(vk.physical(), surface, &n, formats.data()),
           "vkGetPhysicalDeviceSurfaceFormatsKHR");
  if (formats.empty()) throw VulkanError("the window's surface offers no format");
  format_ = formats[0].format;
  color_space_ = formats[0].colorSpace;
  for (const VkSurfaceFormatKHR& f : formats)
    if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) {
      format_ = f.format;
      color_space_ = f.colorSpace;
      break;
    }
  VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  vk_check(vkCreateSemaphore(vk.device(), &semaphore, nullptr, &acquired_), "vkCreateSemaphore");
}

SwapchainTarget::~SwapchainTarget() {
  vkDeviceWaitIdle(vk_.device());
  destroy_swapchain();
  vkDestroySemaphore(vk_.device(), acquired_, nullptr);
}

void SwapchainTarget::destroy_swapchain() {
  VkDevice d = vk_.device();
  attachments_.reset();  // its framebuffers with it
  framebuffers_.clear();
  for (VkImageView v : views_) vkDestroyImageView(d, v, nullptr);
  views_.clear();
  for (VkSemaphore s : rendered_) vkDestroySemaphore(d, s, nullptr);
  rendered_.clear();
  if (swapchain_) vkDestroySwapchainKHR(d, swapchain_, nullptr);
  swapchain_ = VK_NULL_HANDLE;
}

void SwapchainTarget::create(const Renderer& renderer, VkExtent2D extent) {
  vkDeviceWaitIdle(vk_.device());
  destroy_swapchain();
  VkSurfaceCapabilitiesKHR caps;
  vk_check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(vk_.physical(), surface_, &caps),
           "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");
  extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : extent;
  extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent_.height = std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  uint32_t images = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) images = std::min(images, caps.maxImageCount);
  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = images;
  info.imageFormat = format_;
  info.imageColorSpace = color_space_;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : static_cast<VkCompositeAlphaFlagBitsKHR>(caps.supportedCompositeAlpha &
                                                                       (~caps.supportedCompositeAlpha + 1));
  info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
  info.clipped = VK_TRUE;
  vk_check(vkCreateSwapchainKHR(vk_.device(), &info, nullptr, &swapchain_), "vkCreateSwapchainKHR");
  uint32_t n = 0;
  vk_check(vkGetSwapchainImagesKHR(vk_.device(), swapchain_, &n, nullptr), "vkGetSwapchainImagesKHR");
  std::vector<VkImage> list(n);
  vk_check(vkGetSwapchainImagesKHR(vk_.device(), swapchain_, &n, list.data()), "vkGetSwapchainImagesKHR");
  attachments_ = std::make_unique<Attachments>(vk_, format_, extent_, renderer.samples());
  for (VkImage image : list) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView v;
    vk_check(vkCreateImageView(vk_.device(), &view, nullptr, &v), "vkCreateImageView");
    views_.push_back(v);
    framebuffers_.push_back(attachments_->framebuffer(renderer.render_pass(), v, extent_));
    VkSemaphoreCreateInfo semaphore{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s;
    vk_check(vkCreateSemaphore(vk_.device(), &semaphore, nullptr, &s), "vkCreateSemaphore");
    rendered_.push_back(s);
  }
}

bool SwapchainTarget::acquire(VkFramebuffer* fb) {
  const VkResult r =
      vkAcquireNextImageKHR(vk_.device(), swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index_);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (r != VK_SUBOPTIMAL_KHR) vk_check(r, "vkAcquireNextImageKHR");
  *fb = framebuffers_[index_];
  return true;
}

bool SwapchainTarget::present() {
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &rendered_[index_];
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index_;
  const VkResult r = vkQueuePresentKHR(vk_.queue(), &info);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
  vk_check(r, "vkQueuePresentKHR");
  return true;
}

}  // namespace viewer
