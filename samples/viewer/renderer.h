// The renderer: one render pass (MSAA colour resolved into the target's
// image, depth), the mesh pipeline (and its blended twin for the ghost) and
// the lines pipeline (segments as
// screen-space quads from a storage buffer), and the frame's recording.
// Independent of where the image goes (targets.h).
#pragma once

#include "draw_list.h"
#include "render_mesh.h"
#include "vulkan_context.h"

#include <glm/glm.hpp>

#include <functional>
#include <vector>

namespace viewer {

struct FrameInput {
  glm::mat4 view{1.0f}, proj{1.0f};
  glm::mat4 model_a{1.0f}, model_tool{1.0f};
  bool meshes = true;
  // The tool's mesh once more, see-through, where the device holds it (a
  // constrained tool's device pose, when the tool is held back).
  bool ghost = false;
  glm::mat4 model_ghost{1.0f};
  const DrawList* lines = nullptr;
  std::function<void(VkCommandBuffer)> overlay;  // recorded last in the render pass (the text HUD)
};

// Lines on a surface are pulled this much towards the eye (NDC depth):
// pipeline depth bias does not apply to lines drawn as quads of their own.
constexpr float kLineDepthOffset = 2e-4f;

class Renderer {
 public:
  // final_layout: where the target's image is left (transfer source for a
  // read-back, present source for a swapchain).
  Renderer(VulkanContext& vk, VkFormat color_format, VkImageLayout final_layout,
           VkSampleCountFlagBits samples);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  VkRenderPass render_pass() const { return render_pass_; }
  VkSampleCountFlagBits samples() const { return samples_; }
  // The two meshes (the same one twice when A is B).
  void set_meshes(const RenderMesh& a, const RenderMesh& tool);
  // An animated mesh's new vertices (the count set_meshes gave), written
  // into its mapped buffer once the frame in flight is done with it.
  void update_vertices(bool tool, const std::vector<float>& positions);
  // Records the render pass into framebuffer fb.
  void record(VkCommandBuffer cmd, VkFramebuffer fb, VkExtent2D extent, const FrameInput& in);

 private:
  struct GpuMesh {
    Buffer vertices, indices;
    uint32_t index_count = 0;
  };
  void create_pipelines();
  void upload(GpuMesh& m, const RenderMesh& mesh);
  void reserve_lines(std::size_t points);
  void draw_mesh(VkCommandBuffer cmd, const GpuMesh& m, const glm::mat4& view, const glm::mat4& proj,
                 const glm::mat4& model, const glm::vec4& color);

  VulkanContext& vk_;
  VkSampleCountFlagBits samples_;
  VkRenderPass render_pass_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout mesh_layout_ = VK_NULL_HANDLE, lines_layout_ = VK_NULL_HANDLE;
  VkPipeline mesh_pipeline_ = VK_NULL_HANDLE, lines_pipeline_ = VK_NULL_HANDLE;
  VkPipeline ghost_pipeline_ = VK_NULL_HANDLE;  // the mesh pipeline, blended, no depth writes
  GpuMesh mesh_a_, mesh_tool_;
  bool same_mesh_ = false;
  Buffer lines_;
  std::size_t lines_capacity_ = 0;  // points
};

}  // namespace viewer
