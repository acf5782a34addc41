#include "renderer.h"

#include "shader_lines_frag.h"
#include "shader_lines_vert.h"
#include "shader_mesh_frag.h"
#include "shader_mesh_vert.h"

#include <cstring>

namespace viewer {

namespace {

struct MeshPush {
  glm::mat4 mvp;
  glm::vec4 rotation[3];
  glm::vec4 color;
};
static_assert(sizeof(MeshPush) == 128, "shaders/mesh.vert's push constants (the guaranteed 128 bytes)");

struct LinesPush {
  glm::mat4 view_proj;
  glm::vec2 viewport;
  float depth_offset;
  float pad;
};

template <std::size_t N>
VkShaderModule shader(VkDevice device, const uint32_t (&code)[N]) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = sizeof code;
  info.pCode = code;
  VkShaderModule m;
  vk_check(vkCreateShaderModule(device, &info, nullptr, &m), "vkCreateShaderModule");
  return m;
}

}  // namespace

Renderer::Renderer(VulkanContext& vk, VkFormat color_format, VkImageLayout final_layout,
                   VkSampleCountFlagBits samples)
    : vk_(vk), samples_(samples) {
  const bool resolve = samples != VK_SAMPLE_COUNT_1_BIT;
  VkAttachmentDescription att[3] = {};
  att[0].format = color_format;  // the multisampled colour, or the target itself
  att[0].samples = samples;
  att[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  att[0].storeOp = resolve ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE;
  att[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  att[0].finalLayout = resolve ? VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL : final_layout;
  att[1] = att[0];
  att[1].format = VK_FORMAT_D32_SFLOAT;
  att[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  att[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  att[2] = att[0];  // the resolve target
  att[2].samples = VK_SAMPLE_COUNT_1_BIT;
  att[2].loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  att[2].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  att[2].finalLayout = final_layout;
  const VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference target{2, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth;
  if (resolve) subpass.pResolveAttachments = &target;
  // In: the previous frame's attachment writes and its read-back (or
  // presentation, through the acquire semaphore) come before this frame's
  // writes. Out: the writes come before a read-back.
  const VkPipelineStageFlags attachments = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                           VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                           VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  VkSubpassDependency deps[2] = {};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = attachments | VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  deps[0].dstStageMask = attachments;
  deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                          VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = resolve ? 3 : 2;
  info.pAttachments = att;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 2;
  info.pDependencies = deps;
  vk_check(vkCreateRenderPass(vk_.device(), &info, nullptr, &render_pass_), "vkCreateRenderPass");

  VkDescriptorSetLayoutBinding binding{};
  binding.binding = 0;
  binding.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  binding.descriptorCount = 1;
  binding.stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
  VkDescriptorSetLayoutCreateInfo set{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set.bindingCount = 1;
  set.pBindings = &binding;
  vk_check(vkCreateDescriptorSetLayout(vk_.device(), &set, nullptr, &set_layout_),
           "vkCreateDescriptorSetLayout");
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
  VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool.maxSets = 1;
  pool.poolSizeCount = 1;
  pool.pPoolSizes = &size;
  vk_check(vkCreateDescriptorPool(vk_.device(), &pool, nullptr, &pool_), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &set_layout_;
  vk_check(vkAllocateDescriptorSets(vk_.device(), &alloc, &set_), "vkAllocateDescriptorSets");
  create_pipelines();
  reserve_lines(1 << 14);
}

Renderer::~Renderer() {
  VkDevice d = vk_.device();
  vkDeviceWaitIdle(d);
  for (GpuMesh* m : {&mesh_a_, &mesh_tool_}) {
    vk_.destroy(m->vertices);
    vk_.destroy(m->indices);
  }
  vk_.destroy(lines_);
  vkDestroyPipeline(d, mesh_pipeline_, nullptr);
  vkDestroyPipeline(d, ghost_pipeline_, nullptr);
  vkDestroyPipeline(d, lines_pipeline_, nullptr);
  vkDestroyPipelineLayout(d, mesh_layout_, nullptr);
  vkDestroyPipelineLayout(d, lines_layout_, nullptr);
  vkDestroyDescriptorPool(d, pool_, nullptr);
  vkDestroyDescriptorSetLayout(d, set_layout_, nullptr);
  vkDestroyRenderPass(d, render_pass_, nullptr);
}

void Renderer::create_pipelines() {
  VkDevice d = vk_.device();
  VkPushConstantRange mesh_push{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                                sizeof(MeshPush)};
  VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout.pushConstantRangeCount = 1;
  layout.pPushConstantRanges = &mesh_push;
  vk_check(vkCreatePipelineLayout(d, &layout, nullptr, &mesh_layout_), "vkCreatePipelineLayout");
  VkPushConstantRange lines_push{VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof(LinesPush)};
  layout.pPushConstantRanges = &lines_push;
  layout.setLayoutCount = 1;
  layout.pSetLayouts = &set_layout_;
  vk_check(vkCreatePipelineLayout(d, &layout, nullptr, &lines_layout_), "vkCreatePipelineLayout");

  VkShaderModule mesh_vs = shader(d, shader_mesh_vert), mesh_fs = shader(d, shader_mesh_frag);
  VkShaderModule lines_vs = shader(d, shader_lines_vert), lines_fs = shader(d, shader_lines_frag);

  VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                               {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].pName = "main";
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].pName = "main";

  const VkVertexInputBindingDescription binding{0, 3 * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
  const VkVertexInputAttributeDescription attribute{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0};
  VkPipelineVertexInputStateCreateInfo vertex_input{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = samples_;
  VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
  VkPipelineColorBlendAttachmentState blend_attachment{};
  blend_attachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                    VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blend_attachment;
  const VkDynamicState dynamic_states[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = 2;
  dynamic.pDynamicStates = dynamic_states;

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertex_input;
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamic;
  info.renderPass = render_pass_;

  stages[0].module = mesh_vs;
  stages[1].module = mesh_fs;
  vertex_input.vertexBindingDescriptionCount = 1;
  vertex_input.pVertexBindingDescriptions = &binding;
  vertex_input.vertexAttributeDescriptionCount = 1;
  vertex_input.pVertexAttributeDescriptions = &attribute;
  info.layout = mesh_layout_;
  vk_check(vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &mesh_pipeline_),
           "vkCreateGraphicsPipelines (meshes)");
  // The ghost: blended over everything drawn before it, without the depth
  // test (where the device went inside a body, the ghost is in there) and
  // without writing depth, so what it covers stays visible through it.
  blend_attachment.blendEnable = VK_TRUE;
  blend_attachment.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
  blend_attachment.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend_attachment.colorBlendOp = VK_BLEND_OP_ADD;
  blend_attachment.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend_attachment.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
  blend_attachment.alphaBlendOp = VK_BLEND_OP_ADD;
  depth.depthTestEnable = VK_FALSE;
  depth.depthWriteEnable = VK_FALSE;
  vk_check(vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &ghost_pipeline_),
           "vkCreateGraphicsPipelines (ghost)");
  blend_attachment.blendEnable = VK_FALSE;
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;

  stages[0].module = lines_vs;
  stages[1].module = lines_fs;
  vertex_input =
      VkPipelineVertexInputStateCreateInfo{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  info.layout = lines_layout_;
  vk_check(vkCreateGraphicsPipelines(d, VK_NULL_HANDLE, 1, &info, nullptr, &lines_pipeline_),
           "vkCreateGraphicsPipelines (lines)");

  for (VkShaderModule m : {mesh_vs, mesh_fs, lines_vs, lines_fs}) vkDestroyShaderModule(d, m, nullptr);
}

void Renderer::upload(GpuMesh& m, const RenderMesh& mesh) {
  const VkDeviceSize vbytes = mesh.positions.size() * sizeof(float);
  const VkDeviceSize ibytes = mesh.indices.size() * sizeof(uint32_t);
  m.vertices = vk_.create_buffer(vbytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  m.indices = vk_.create_buffer(ibytes, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  std::memcpy(m.vertices.mapped, mesh.positions.data(), vbytes);
  std::memcpy(m.indices.mapped, mesh.indices.data(), ibytes);
  m.index_count = static_cast<uint32_t>(mesh.indices.size());
}

void Renderer::set_meshes(const RenderMesh& a, const RenderMesh& tool) {
  upload(mesh_a_, a);
  same_mesh_ = &a == &tool;
  if (!same_mesh_) upload(mesh_tool_, tool);
}

void Renderer::update_vertices(bool tool, const std::vector<float>& positions) {
  GpuMesh& m = tool && !same_mesh_ ? mesh_tool_ : mesh_a_;
  const VkDeviceSize bytes = positions.size() * sizeof(float);
  if (bytes != m.vertices.size) throw VulkanError("update_vertices: the vertex count changed");
  vk_.wait_frame();  // the frame in flight may still read them
  std::memcpy(m.vertices.mapped, positions.data(), bytes);
}

void Renderer::reserve_lines(std::size_t points) {
  if (points <= lines_capacity_) return;
  vk_.wait_frame();  // the buffer may still be read by the frame in flight
  std::size_t capacity = lines_capacity_ ? lines_capacity_ : 1;
  while (capacity < points) capacity *= 2;
  vk_.destroy(lines_);
  lines_ = vk_.create_buffer(capacity * sizeof(LinePoint), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  lines_capacity_ = capacity;
  VkDescriptorBufferInfo buffer{lines_.buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstSet = set_;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &buffer;
  vkUpdateDescriptorSets(vk_.device(), 1, &write, 0, nullptr);
}

void Renderer::draw_mesh(VkCommandBuffer cmd, const GpuMesh& m, const glm::mat4& view, const glm::mat4& proj,
                         const glm::mat4& model, const glm::vec4& color) {
  MeshPush push;
  const glm::mat4 mv = view * model;
  push.mvp = proj * mv;
  for (int r = 0; r < 3; ++r) push.rotation[r] = glm::vec4(mv[0][r], mv[1][r], mv[2][r], 0.0f);
  push.color = color;
  vkCmdPushConstants(cmd, mesh_layout_, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                     sizeof push, &push);
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &m.vertices.buffer, &offset);
  vkCmdBindIndexBuffer(cmd, m.indices.buffer, 0, VK_INDEX_TYPE_UINT32);
  vkCmdDrawIndexed(cmd, m.index_count, 1, 0, 0, 0);
}

void Renderer::record(VkCommandBuffer cmd, VkFramebuffer fb, VkExtent2D extent, const FrameInput& in) {
  const std::size_t world = in.lines ? in.lines->world.size() : 0;
  const std::size_t screen = in.lines ? in.lines->screen.size() : 0;
  reserve_lines(world + screen);
  if (world) std::memcpy(lines_.mapped, in.lines->world.data(), world * sizeof(LinePoint));
  if (screen)
    std::memcpy(static_cast<LinePoint*>(lines_.mapped) + world, in.lines->screen.data(),
                screen * sizeof(LinePoint));

  VkClearValue clear[3] = {};
  clear[0].color = {{kBackground.r, kBackground.g, kBackground.b, 1.0f}};
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = render_pass_;
  begin.framebuffer = fb;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = 2;
  begin.pClearValues = clear;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  const VkViewport viewport{0.0f, 0.0f, static_cast<float>(extent.width), static_cast<float>(extent.height),
                            0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);

  if (in.meshes) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mesh_pipeline_);
    draw_mesh(cmd, mesh_a_, in.view, in.proj, in.model_a, kOtherColor);
    draw_mesh(cmd, same_mesh_ ? mesh_a_ : mesh_tool_, in.view, in.proj, in.model_tool, kToolColor);
  }
  if (world + screen > 0) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lines_pipeline_);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, lines_layout_, 0, 1, &set_, 0, nullptr);
    LinesPush push{in.proj * in.view, glm::vec2(extent.width, extent.height), kLineDepthOffset, 0.0f};
    if (world) {
      vkCmdPushConstants(cmd, lines_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
      vkCmdDraw(cmd, 6, static_cast<uint32_t>(world / 2), 0, 0);
    }
    if (screen) {
      // Pixels to NDC (y already points down), at the near plane, not offset.
      glm::mat4 pixels(1.0f);
      pixels[0][0] = 2.0f / static_cast<float>(extent.width);
      pixels[1][1] = 2.0f / static_cast<float>(extent.height);
      pixels[3] = glm::vec4(-1.0f, -1.0f, 0.0f, 1.0f);
      push.view_proj = pixels;
      push.depth_offset = 0.0f;
      vkCmdPushConstants(cmd, lines_layout_, VK_SHADER_STAGE_VERTEX_BIT, 0, sizeof push, &push);
      vkCmdDraw(cmd, 6, static_cast<uint32_t>(screen / 2), 0, static_cast<uint32_t>(world / 2));
    }
  }
  if (in.ghost) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, ghost_pipeline_);
    draw_mesh(cmd, same_mesh_ ? mesh_a_ : mesh_tool_, in.view, in.proj, in.model_ghost, kGhostColor);
  }
  if (in.overlay) in.overlay(cmd);
  vkCmdEndRenderPass(cmd);
}

}  // namespace viewer
