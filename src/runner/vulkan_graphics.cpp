// Vulkan graphics backend: the wrapped stage pair (graphics_wrapper.hpp) as a lavapipe graphics
// pipeline drawing points into a render pass without attachments; inputs and outputs are the
// wrapper's storage buffers (set 0), loose uniforms the glslang global block (set kUniformSet).
#include <vulkan/vulkan.h>

#include "runner/graphics_wrapper.hpp"
#include "runner/vulkan_device.hpp"

namespace doublet::runner::detail {
namespace {

constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

struct GraphicsPipeline {
  VkDescriptorSetLayout layouts[2] = {};
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkCommandPool cmd_pool = VK_NULL_HANDLE;
};

std::string make_module(VulkanDevice& d, JobObjects& objs, const std::vector<uint32_t>& words, VkShaderModule* out) {
  VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smci.codeSize = words.size() * sizeof(uint32_t);
  smci.pCode = words.data();
  if (VkResult r = vkCreateShaderModule(d.device, &smci, nullptr, out); r != VK_SUCCESS)
    return vk_failed("vkCreateShaderModule", r);
  VkShaderModule m = *out;
  objs.cleanup.push_back([&d, m] { vkDestroyShaderModule(d.device, m, nullptr); });
  return {};
}

std::string make_layouts(VulkanDevice& d, JobObjects& objs, GraphicsPipeline* p) {
  static_assert(kUniformSet == 1 && kUniformBinding == 0, "layout below assumes set 1, binding 0");
  const VkDescriptorSetLayoutBinding ssbos[2] = {
      {kInputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kStages, nullptr},
      {kOutputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kStages, nullptr}};
  const VkDescriptorSetLayoutBinding ubo{kUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kStages, nullptr};
  for (int s = 0; s < 2; ++s) {
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = s == 0 ? 2 : 1;
    lci.pBindings = s == 0 ? ssbos : &ubo;
    if (VkResult r = vkCreateDescriptorSetLayout(d.device, &lci, nullptr, &p->layouts[s]); r != VK_SUCCESS)
      return vk_failed("vkCreateDescriptorSetLayout", r);
    VkDescriptorSetLayout l = p->layouts[s];
    objs.cleanup.push_back([&d, l] { vkDestroyDescriptorSetLayout(d.device, l, nullptr); });
  }
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 2;
  plci.pSetLayouts = p->layouts;
  if (VkResult r = vkCreatePipelineLayout(d.device, &plci, nullptr, &p->layout); r != VK_SUCCESS)
    return vk_failed("vkCreatePipelineLayout", r);
  VkPipelineLayout layout = p->layout;
  objs.cleanup.push_back([&d, layout] { vkDestroyPipelineLayout(d.device, layout, nullptr); });
  return {};
}

// A render pass and framebuffer without attachments: the fragment stage only stores to buffers.
std::string make_render_target(VulkanDevice& d, JobObjects& objs, GraphicsPipeline* p) {
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkRenderPassCreateInfo rpci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  rpci.subpassCount = 1;
  rpci.pSubpasses = &subpass;
  if (VkResult r = vkCreateRenderPass(d.device, &rpci, nullptr, &p->render_pass); r != VK_SUCCESS)
    return vk_failed("vkCreateRenderPass", r);
  VkRenderPass rp = p->render_pass;
  objs.cleanup.push_back([&d, rp] { vkDestroyRenderPass(d.device, rp, nullptr); });
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = rp;
  fci.width = kGridWidth;
  fci.height = kGridHeight;
  fci.layers = 1;
  if (VkResult r = vkCreateFramebuffer(d.device, &fci, nullptr, &p->framebuffer); r != VK_SUCCESS)
    return vk_failed("vkCreateFramebuffer", r);
  VkFramebuffer fb = p->framebuffer;
  objs.cleanup.push_back([&d, fb] { vkDestroyFramebuffer(d.device, fb, nullptr); });
  return {};
}

std::string make_pipeline(VulkanDevice& d, const SpirvProgram& program, GraphicsStage stage, JobObjects& objs,
                          GraphicsPipeline* p) {
  if (std::string e = make_layouts(d, objs, p); !e.empty()) return e;
  if (std::string e = make_render_target(d, objs, p); !e.empty()) return e;
  VkShaderModule modules[2];
  if (std::string e = make_module(d, objs, program.words, &modules[0]); !e.empty()) return e;
  if (std::string e = make_module(d, objs, program.fragment_words, &modules[1]); !e.empty()) return e;
  VkPipelineShaderStageCreateInfo stages[2];
  for (int i = 0; i < 2; ++i) {
    stages[i] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    stages[i].stage = i == 0 ? VK_SHADER_STAGE_VERTEX_BIT : VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  const VkViewport viewport{0, 0, static_cast<float>(kGridWidth), static_cast<float>(kGridHeight), 0, 1};
  const VkRect2D scissor{{0, 0}, {kGridWidth, kGridHeight}};
  VkPipelineViewportStateCreateInfo viewport_state{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport_state.viewportCount = 1;
  viewport_state.pViewports = &viewport;
  viewport_state.scissorCount = 1;
  viewport_state.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.rasterizerDiscardEnable = stage == GraphicsStage::Vertex ? VK_TRUE : VK_FALSE;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkGraphicsPipelineCreateInfo gpci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  gpci.stageCount = 2;
  gpci.pStages = stages;
  gpci.pVertexInputState = &vertex_input;
  gpci.pInputAssemblyState = &assembly;
  gpci.pViewportState = &viewport_state;
  gpci.pRasterizationState = &raster;
  gpci.pMultisampleState = &multisample;
  gpci.layout = p->layout;
  gpci.renderPass = p->render_pass;
  if (VkResult r = vkCreateGraphicsPipelines(d.device, VK_NULL_HANDLE, 1, &gpci, nullptr, &p->pipeline); r != VK_SUCCESS)
    return vk_failed("vkCreateGraphicsPipelines", r);
  VkPipeline pipeline = p->pipeline;
  objs.cleanup.push_back([&d, pipeline] { vkDestroyPipeline(d.device, pipeline, nullptr); });
  VkCommandPoolCreateInfo cpool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  cpool.queueFamilyIndex = d.queue_family;
  if (VkResult r = vkCreateCommandPool(d.device, &cpool, nullptr, &p->cmd_pool); r != VK_SUCCESS)
    return vk_failed("vkCreateCommandPool", r);
  VkCommandPool pool = p->cmd_pool;
  objs.cleanup.push_back([&d, pool] { vkDestroyCommandPool(d.device, pool, nullptr); });
  return {};
}

// One draw with the job's buffers and uniforms; its objects die with the call.
std::string draw(VulkanDevice& d, const WrappedProgram& w, const SpirvProgram& program, const GraphicsPipeline& p,
                 const GraphicsJob& job, uint32_t count, GraphicsResult* result) {
  std::vector<uint8_t> ubo_data, input_data;
  if (std::string e = uniform_block_bytes(program, job.float_uniforms, job.uniforms, &ubo_data); !e.empty()) return e;
  if (std::string e = pack_inputs(w.iface, job, &input_data); !e.empty()) return e;
  JobObjects objs(d.device);
  HostBuffer inputs, outputs, ubo;
  if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, input_data, &inputs); !e.empty()) return e;
  const std::vector<uint8_t> blank = blank_outputs(w.iface, count);
  if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, blank, &outputs); !e.empty()) return e;
  if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, ubo_data, &ubo); !e.empty()) return e;

  const VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2}, {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}};
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 2;
  dpci.poolSizeCount = 2;
  dpci.pPoolSizes = sizes;
  VkDescriptorPool pool;
  if (VkResult r = vkCreateDescriptorPool(d.device, &dpci, nullptr, &pool); r != VK_SUCCESS)
    return vk_failed("vkCreateDescriptorPool", r);
  objs.cleanup.push_back([&d, pool] { vkDestroyDescriptorPool(d.device, pool, nullptr); });
  VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dsai.descriptorPool = pool;
  dsai.descriptorSetCount = 2;
  dsai.pSetLayouts = p.layouts;
  VkDescriptorSet sets[2];
  if (VkResult r = vkAllocateDescriptorSets(d.device, &dsai, sets); r != VK_SUCCESS)
    return vk_failed("vkAllocateDescriptorSets", r);
  const VkDescriptorBufferInfo infos[3] = {{inputs.buffer, 0, VK_WHOLE_SIZE}, {outputs.buffer, 0, VK_WHOLE_SIZE},
                                           {ubo.buffer, 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[3];
  for (int i = 0; i < 3; ++i) {
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = sets[i == 2 ? 1 : 0];
    writes[i].dstBinding = i == 0 ? kInputBinding : i == 1 ? kOutputBinding : kUniformBinding;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = i == 2 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(d.device, 3, writes, 0, nullptr);

  VkCommandBuffer cmd;
  if (std::string error = begin_one_time_commands(d, p.cmd_pool, objs, &cmd); !error.empty()) return error;
  VkRenderPassBeginInfo rpbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rpbi.renderPass = p.render_pass;
  rpbi.framebuffer = p.framebuffer;
  rpbi.renderArea = {{0, 0}, {kGridWidth, kGridHeight}};
  vkCmdBeginRenderPass(cmd, &rpbi, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0, 2, sets, 0, nullptr);
  vkCmdDraw(cmd, count, 1, 0, 0);
  vkCmdEndRenderPass(cmd);
  // Make the stages' buffer stores visible to the host mapping we read back from.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
  if (std::string error = submit_and_wait(d, objs, cmd); !error.empty()) return error;
  unpack_outputs(w.iface, count, static_cast<const uint8_t*>(outputs.mapped), result);
  return {};
}

}  // namespace

std::vector<GraphicsResult> vulkan_run_graphics(const WrappedProgram& w, const SpirvProgram& program,
                                                const std::vector<GraphicsJob>& jobs) {
  VulkanDevice& d = shared_device();
  std::vector<GraphicsResult> results;
  auto fail = [&](std::string error) {
    results.emplace_back();
    results.back().device = d.name;
    results.back().error = std::move(error);
    return results;
  };
  if (!d.error.empty()) return fail("Vulkan unavailable: " + d.error);
  if (!d.graphics || !d.stage_stores)
    return fail(d.name + " cannot run vertex/fragment jobs (needs a graphics queue, vertexPipelineStoresAndAtomics "
                "and fragmentStoresAndAtomics)");
  if ((spirv_uses_float64(program.words) || spirv_uses_float64(program.fragment_words)) && !d.float64)
    return fail("shader uses double (Float64) but " + d.name + " lacks shaderFloat64");
  std::lock_guard<std::mutex> lock(d.mu);
  JobObjects shared(d.device);
  GraphicsPipeline pipeline;
  if (std::string e = make_pipeline(d, program, jobs[0].stage, shared, &pipeline); !e.empty()) return fail(e);
  for (const GraphicsJob& job : jobs) {
    GraphicsResult result;
    result.device = d.name;
    result.error = draw(d, w, program, pipeline, job, jobs[0].count, &result);
    result.ok = result.error.empty();
    if (!result.ok) result.outputs.clear();
    results.push_back(std::move(result));
    if (!results.back().ok) break;
  }
  return results;
}

}  // namespace doublet::runner::detail
