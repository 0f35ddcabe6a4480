// Vulkan graphics backend: the wrapped stage pair (graphics_wrapper.hpp) as a lavapipe graphics
// pipeline drawing points into a render pass without attachments; inputs and outputs are the
// wrapper's storage buffers (set 0), loose uniforms the glslang global block (set kUniformSet).
#include <vulkan/vulkan.h>

#include <algorithm>
#include <map>

#include "runner/graphics_wrapper.hpp"
#include "runner/vulkan_device.hpp"

namespace doublet::runner::detail {
namespace {

constexpr VkShaderStageFlags kStages = VK_SHADER_STAGE_ALL_GRAPHICS;

struct GraphicsPipeline {
  VkDescriptorSetLayout layouts[3] = {};  // set 0: the shader's blocks and samplers; 1: loose uniforms; 2: the wrapper's
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass render_pass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkCommandPool cmd_pool = VK_NULL_HANDLE;
  std::map<TextureKind, SampledTexture> textures;  // the test texture, per kind the shader samples
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

// Set 0: the shader's named uniform blocks and samplers (at their bindings, or glslang's automatic
// ones); set kUniformSet: the global block of loose uniforms; set kWrapperSet: the wrapper's input
// and output buffers.
std::string make_layouts(VulkanDevice& d, const SpirvProgram& program, JobObjects& objs, GraphicsPipeline* p) {
  static_assert(kUniformSet == 1 && kUniformBinding == 0 && kWrapperSet == 2, "layout below assumes sets 1 and 2");
  std::vector<VkDescriptorSetLayoutBinding> set0;
  for (const auto* list : {&program.uniform_blocks, &program.samplers})
    for (const SpirvProgram::Resource& r : *list) {
      const bool sampler = list == &program.samplers;
      if (r.set != 0)  // (OpenGL GLSL has no sets: a resource is always in set 0)
        return "uniform '" + r.name + "' is at set " + std::to_string(r.set) + ", which the runner cannot use (set 0)";
      set0.push_back({r.binding, sampler ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                      1, kStages, nullptr});
    }
  const VkDescriptorSetLayoutBinding ubo{kUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kStages, nullptr};
  const VkDescriptorSetLayoutBinding wrapper[2] = {{kInputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kStages, nullptr},
                                                   {kOutputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kStages, nullptr}};
  for (int s = 0; s < 3; ++s) {
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = s == 0 ? static_cast<uint32_t>(set0.size()) : s == 1 ? 1 : 2;
    lci.pBindings = s == 0 ? set0.data() : s == 1 ? &ubo : wrapper;
    if (VkResult r = vkCreateDescriptorSetLayout(d.device, &lci, nullptr, &p->layouts[s]); r != VK_SUCCESS)
      return vk_failed("vkCreateDescriptorSetLayout", r);
    VkDescriptorSetLayout l = p->layouts[s];
    objs.cleanup.push_back([&d, l] { vkDestroyDescriptorSetLayout(d.device, l, nullptr); });
  }
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 3;
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

std::string make_pipeline(VulkanDevice& d, const SpirvProgram& program, GraphicsStage stage, uint32_t input_vertices,
                          JobObjects& objs, GraphicsPipeline* p) {
  if (std::string e = make_layouts(d, program, objs, p); !e.empty()) return e;
  if (std::string e = make_render_target(d, objs, p); !e.empty()) return e;
  const bool geometry = stage == GraphicsStage::Geometry;
  const bool tessellation = !program.tess_control_words.empty();
  const std::pair<VkShaderStageFlagBits, const std::vector<uint32_t>*> present[] = {
      {VK_SHADER_STAGE_VERTEX_BIT, &program.words},
      {VK_SHADER_STAGE_FRAGMENT_BIT, &program.fragment_words},
      {VK_SHADER_STAGE_GEOMETRY_BIT, &program.geometry_words},
      {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, &program.tess_control_words},
      {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, &program.tess_evaluation_words}};
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  for (const auto& [kind, words] : present) {
    if (words->empty()) continue;
    VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    if (std::string e = make_module(d, objs, *words, &info.module); !e.empty()) return e;
    info.stage = kind;
    info.pName = "main";
    stages.push_back(info);
  }
  VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  // A geometry job draws primitives of the shader's input type, one per sample.
  switch (geometry ? input_vertices : 1) {
    case 2: assembly.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST; break;
    case 3: assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST; break;
    case 4: assembly.topology = VK_PRIMITIVE_TOPOLOGY_LINE_LIST_WITH_ADJACENCY; break;
    case 6: assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY; break;
    default: break;
  }
  // A tessellation job draws one patch per sample.
  VkPipelineTessellationStateCreateInfo patches{VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
  patches.patchControlPoints = input_vertices;
  if (tessellation) assembly.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  const VkViewport viewport{0, 0, static_cast<float>(kGridWidth), static_cast<float>(kGridHeight), 0, 1};
  const VkRect2D scissor{{0, 0}, {kGridWidth, kGridHeight}};
  VkPipelineViewportStateCreateInfo viewport_state{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport_state.viewportCount = 1;
  viewport_state.pViewports = &viewport;
  viewport_state.scissorCount = 1;
  viewport_state.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.rasterizerDiscardEnable = stage == GraphicsStage::Fragment ? VK_FALSE : VK_TRUE;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkGraphicsPipelineCreateInfo gpci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  gpci.stageCount = static_cast<uint32_t>(stages.size());
  gpci.pStages = stages.data();
  if (tessellation) gpci.pTessellationState = &patches;
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
  for (const SpirvProgram::Resource& s : program.samplers)
    if (!p->textures.count(s.kind))
      if (std::string e = make_test_texture(d, objs, pool, s.kind, &p->textures[s.kind]); !e.empty()) return e;
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

  // The job's named uniform blocks (zeros for a block it does not give).
  std::vector<HostBuffer> blocks(program.uniform_blocks.size());
  for (size_t i = 0; i < blocks.size(); ++i) {
    const SpirvProgram::Resource& r = program.uniform_blocks[i];
    auto given = job.uniform_blocks.find(r.name);
    std::vector<uint8_t> bytes = given == job.uniform_blocks.end() ? std::vector<uint8_t>() : given->second;
    bytes.resize(std::max<size_t>(bytes.size(), r.size), 0);
    if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, bytes, &blocks[i]); !e.empty()) return e;
  }

  const auto block_count = static_cast<uint32_t>(blocks.size());
  const auto sampler_count = static_cast<uint32_t>(program.samplers.size());
  std::vector<VkDescriptorPoolSize> sizes = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2},
                                             {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1 + block_count}};
  if (sampler_count) sizes.push_back({VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, sampler_count});
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 3;
  dpci.poolSizeCount = static_cast<uint32_t>(sizes.size());
  dpci.pPoolSizes = sizes.data();
  VkDescriptorPool pool;
  if (VkResult r = vkCreateDescriptorPool(d.device, &dpci, nullptr, &pool); r != VK_SUCCESS)
    return vk_failed("vkCreateDescriptorPool", r);
  objs.cleanup.push_back([&d, pool] { vkDestroyDescriptorPool(d.device, pool, nullptr); });
  VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dsai.descriptorPool = pool;
  dsai.descriptorSetCount = 3;
  dsai.pSetLayouts = p.layouts;
  VkDescriptorSet sets[3];
  if (VkResult r = vkAllocateDescriptorSets(d.device, &dsai, sets); r != VK_SUCCESS)
    return vk_failed("vkAllocateDescriptorSets", r);
  // Buffers: input, output, global uniforms, then the named blocks; then the samplers.
  std::vector<VkDescriptorBufferInfo> buffer_infos = {{inputs.buffer, 0, VK_WHOLE_SIZE},
                                                      {outputs.buffer, 0, VK_WHOLE_SIZE},
                                                      {ubo.buffer, 0, VK_WHOLE_SIZE}};
  for (const HostBuffer& b : blocks) buffer_infos.push_back({b.buffer, 0, VK_WHOLE_SIZE});
  std::vector<VkDescriptorImageInfo> image_infos;
  for (const SpirvProgram::Resource& s : program.samplers) {
    const SampledTexture& t = p.textures.at(s.kind);
    image_infos.push_back({t.sampler, t.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  }
  std::vector<VkWriteDescriptorSet> writes;
  auto write = [&](VkDescriptorSet set, uint32_t binding, VkDescriptorType type) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = set;
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    writes.push_back(w);
  };
  write(sets[kWrapperSet], kInputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  write(sets[kWrapperSet], kOutputBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  write(sets[1], kUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  for (const SpirvProgram::Resource& r : program.uniform_blocks)
    write(sets[0], r.binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
  for (const SpirvProgram::Resource& r : program.samplers)
    write(sets[0], r.binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
  for (size_t i = 0; i < writes.size(); ++i) {
    if (i < buffer_infos.size()) writes[i].pBufferInfo = &buffer_infos[i];
    else writes[i].pImageInfo = &image_infos[i - buffer_infos.size()];
  }
  vkUpdateDescriptorSets(d.device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);

  VkCommandBuffer cmd;
  if (std::string error = begin_one_time_commands(d, p.cmd_pool, objs, &cmd); !error.empty()) return error;
  VkRenderPassBeginInfo rpbi{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rpbi.renderPass = p.render_pass;
  rpbi.framebuffer = p.framebuffer;
  rpbi.renderArea = {{0, 0}, {kGridWidth, kGridHeight}};
  vkCmdBeginRenderPass(cmd, &rpbi, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0, 3, sets, 0, nullptr);
  vkCmdDraw(cmd, count * w.iface.input_vertices, 1, 0, 0);
  vkCmdEndRenderPass(cmd);
  // Make the stages' buffer stores visible to the host mapping we read back from.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_GRAPHICS_BIT,
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
  if (jobs[0].stage == GraphicsStage::Geometry && !d.geometry) return fail(d.name + " has no geometryShader feature");
  if (!program.tess_control_words.empty() && !d.tessellation) return fail(d.name + " has no tessellationShader feature");
  if ((spirv_uses_float64(program.words) || spirv_uses_float64(program.fragment_words) ||
       spirv_uses_float64(program.geometry_words) || spirv_uses_float64(program.tess_control_words) ||
       spirv_uses_float64(program.tess_evaluation_words)) && !d.float64)
    return fail("shader uses double (Float64) but " + d.name + " lacks shaderFloat64");
  std::lock_guard<std::mutex> lock(d.mu);
  JobObjects shared(d.device);
  GraphicsPipeline pipeline;
  if (std::string e = make_pipeline(d, program, jobs[0].stage, w.iface.input_vertices, shared, &pipeline); !e.empty())
    return fail(e);
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
