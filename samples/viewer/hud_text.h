// The HUD as text, through Dear ImGui's Vulkan backend (Debian's
// libimgui-dev): frame time, the threads' rates and p99 periods, the LMD
// count, force and torque, method, force preset and device. Built when
// CMake finds ImGui; without it the viewer draws hud.h's bars instead.
#pragma once

#include "hud.h"
#include "vulkan_context.h"

namespace viewer {

class TextHud {
 public:
  // Uploads the font with one submission on vk's frame command buffer.
  TextHud(VulkanContext& vk, VkRenderPass pass, VkSampleCountFlagBits samples);
  ~TextHud();
  TextHud(const TextHud&) = delete;
  TextHud& operator=(const TextHud&) = delete;

  // Lays out this frame's panel (before recording).
  void build(const HudState& hud, VkExtent2D extent);
  // Draws it; inside the render pass, after everything else.
  void record(VkCommandBuffer cmd);

 private:
  void layout(const HudState& hud);
  VulkanContext& vk_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  bool laid_out_ = false;
};

}  // namespace viewer
