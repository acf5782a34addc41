#include "hud_text.h"

#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include <algorithm>

namespace viewer {

namespace {

void check_imgui(VkResult r) {
  if (r < 0) vk_check(r, "ImGui's Vulkan backend");
}

}  // namespace

TextHud::TextHud(VulkanContext& vk, VkRenderPass pass, VkSampleCountFlagBits samples) : vk_(vk) {
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = 1;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  vk_check(vkCreateDescriptorPool(vk.device(), &info, nullptr, &pool_), "vkCreateDescriptorPool (HUD)");

  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // nothing written beside the user's files
  io.LogFilename = nullptr;
  ImGui::StyleColorsDark();
  ImGui_ImplVulkan_InitInfo init{};
  init.Instance = vk.instance();
  init.PhysicalDevice = vk.physical();
  init.Device = vk.device();
  init.QueueFamily = vk.queue_family();
  init.Queue = vk.queue();
  init.DescriptorPool = pool_;
  init.MinImageCount = 2;
  init.ImageCount = 2;
  init.MSAASamples = samples;
  init.CheckVkResultFn = check_imgui;
  if (!ImGui_ImplVulkan_Init(&init, pass)) throw VulkanError("ImGui's Vulkan backend did not start");
  VkCommandBuffer cmd = vk.begin_frame();
  ImGui_ImplVulkan_CreateFontsTexture(cmd);
  vk.submit(VK_NULL_HANDLE, 0, VK_NULL_HANDLE);
  vk.wait_frame();
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

TextHud::~TextHud() {
  vkDeviceWaitIdle(vk_.device());
  ImGui_ImplVulkan_Shutdown();
  ImGui::DestroyContext();
  vkDestroyDescriptorPool(vk_.device(), pool_, nullptr);
}

void TextHud::build(const HudState& hud, VkExtent2D extent) {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(extent.width), static_cast<float>(extent.height));
  io.DeltaTime = static_cast<float>(std::max(hud.frame_seconds, 1e-3));
  // An auto-sized window is measured in its first frame and shown from the
  // second: lay the first one out twice, so that frame 0 has its HUD.
  if (!laid_out_) layout(hud);
  laid_out_ = true;
  layout(hud);
}

void TextHud::layout(const HudState& hud) {
  ImGui_ImplVulkan_NewFrame();
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f));
  ImGui::SetNextWindowBgAlpha(0.6f);
  ImGui::Begin("proxima", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  if (hud.frame_seconds > 0.0)
    ImGui::Text("frame   %6.1f ms", hud.frame_seconds * 1e3);
  else
    ImGui::Text("frame   the first");
  const char* names[3] = {"haptic", "local ", "global"};
  for (int t = 0; t < 3; ++t) {
    if (hud.threads && hud.threads[t].running)
      ImGui::Text("%s  %6.0f Hz  p99 %.2f ms", names[t], hud.threads[t].achievedRate,
                  hud.threads[t].periodP99 * 1e3);
    else
      ImGui::Text("%s  stepped %s", names[t], hud.stepped_each_frame ? "each frame" : "once");
  }
  ImGui::Text("LMDs    %zu", hud.contacts);
  ImGui::Text("force   %.3f N   torque %.4f N m", hud.force, hud.torque);
  ImGui::Text("%s, %s force, device %s", method_name(hud.method), force_name(hud.preset),
              device_name(hud.device));
  ImGui::End();
  ImGui::Render();
}

void TextHud::record(VkCommandBuffer cmd) { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); }

}  // namespace viewer
