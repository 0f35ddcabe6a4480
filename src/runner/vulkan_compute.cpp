// Vulkan compute backend: each job builds and destroys its own objects on the shared lavapipe device.
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <mutex>

#include "runner/vulkan_device.hpp"

namespace doublet::runner::detail {
namespace {
// What every job of a batch shares: layouts, the pipeline, the command pool.
struct Pipeline {
  VkDescriptorSetLayout layouts[2] = {};
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkCommandPool cmd_pool = VK_NULL_HANDLE;
  uint32_t buffer_count = 0;
};

std::string make_pipeline(VulkanDevice& d, const SpirvProgram& program, uint32_t n, JobObjects& objs, Pipeline* p) {
  p->buffer_count = n;
  // Set 0: SSBO i at binding i. Set kUniformSet: the global uniform block.
  static_assert(kUniformSet == 1 && kUniformBinding == 0, "layout below assumes set 1, binding 0");
  std::vector<VkDescriptorSetLayoutBinding> ssbo_bindings(n);
  for (uint32_t i = 0; i < n; ++i)
    ssbo_bindings[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutBinding ubo_binding{kUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                           VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  for (int s = 0; s < 2; ++s) {
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = s == 0 ? n : 1;
    lci.pBindings = s == 0 ? ssbo_bindings.data() : &ubo_binding;
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
  VkPipelineLayout pipeline_layout = p->layout;
  objs.cleanup.push_back([&d, pipeline_layout] { vkDestroyPipelineLayout(d.device, pipeline_layout, nullptr); });

  VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smci.codeSize = program.words.size() * sizeof(uint32_t);
  smci.pCode = program.words.data();
  VkShaderModule module;
  if (VkResult r = vkCreateShaderModule(d.device, &smci, nullptr, &module); r != VK_SUCCESS)
    return vk_failed("vkCreateShaderModule", r);
  objs.cleanup.push_back([&d, module] { vkDestroyShaderModule(d.device, module, nullptr); });
  VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpci.stage.module = module;
  cpci.stage.pName = "main";
  cpci.layout = pipeline_layout;
  if (VkResult r = vkCreateComputePipelines(d.device, VK_NULL_HANDLE, 1, &cpci, nullptr, &p->pipeline); r != VK_SUCCESS)
    return vk_failed("vkCreateComputePipelines", r);
  VkPipeline pipeline = p->pipeline;
  objs.cleanup.push_back([&d, pipeline] { vkDestroyPipeline(d.device, pipeline, nullptr); });

  VkCommandPoolCreateInfo cpool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  cpool.queueFamilyIndex = d.queue_family;
  if (VkResult r = vkCreateCommandPool(d.device, &cpool, nullptr, &p->cmd_pool); r != VK_SUCCESS)
    return vk_failed("vkCreateCommandPool", r);
  VkCommandPool cmd_pool = p->cmd_pool;
  objs.cleanup.push_back([&d, cmd_pool] { vkDestroyCommandPool(d.device, cmd_pool, nullptr); });
  return {};
}

std::string check_job(VulkanDevice& d, const SpirvProgram& program, const ComputeJob& job, uint32_t n) {
  if (job.buffers.size() != n) return "every job of a batch must have the same number of buffers";
  for (int b : program.ssbo_bindings)
    if (b < 0 || static_cast<size_t>(b) >= job.buffers.size())
      return "shader declares an SSBO at binding " + std::to_string(b) + " but the job has " +
             std::to_string(job.buffers.size()) + " buffer(s)";
  const uint32_t* maxg = d.limits.maxComputeWorkGroupCount;
  if (job.groups_x > maxg[0] || job.groups_y > maxg[1] || job.groups_z > maxg[2])
    return "group count exceeds maxComputeWorkGroupCount";
  return {};
}

// One dispatch with the job's buffers and uniforms; its objects die with the call.
std::string dispatch(VulkanDevice& d, const SpirvProgram& program, const Pipeline& p, const ComputeJob& job,
                     ComputeResult* result) {
  const uint32_t n = p.buffer_count;
  if (std::string e = check_job(d, program, job, n); !e.empty()) return e;
  std::vector<uint8_t> ubo_data;
  if (std::string e = uniform_block_bytes(program, job.float_uniforms, job.uniforms, &ubo_data); !e.empty()) return e;

  JobObjects objs(d.device);
  std::vector<HostBuffer> ssbos(n);
  for (uint32_t i = 0; i < n; ++i)
    if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, job.buffers[i], &ssbos[i]); !e.empty())
      return e;
  HostBuffer ubo;
  if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, ubo_data, &ubo); !e.empty()) return e;

  std::vector<VkDescriptorPoolSize> pool_sizes{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}};
  if (n) pool_sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n});
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 2;
  dpci.poolSizeCount = static_cast<uint32_t>(pool_sizes.size());
  dpci.pPoolSizes = pool_sizes.data();
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

  std::vector<VkDescriptorBufferInfo> infos(n + 1);
  std::vector<VkWriteDescriptorSet> writes(n + 1);
  for (uint32_t i = 0; i <= n; ++i) {
    const bool is_ubo = i == n;
    infos[i] = {is_ubo ? ubo.buffer : ssbos[i].buffer, 0, VK_WHOLE_SIZE};
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = sets[is_ubo ? 1 : 0];
    writes[i].dstBinding = is_ubo ? kUniformBinding : i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = is_ubo ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(d.device, n + 1, writes.data(), 0, nullptr);

  VkCommandBuffer cmd;
  if (std::string error = begin_one_time_commands(d, p.cmd_pool, objs, &cmd); !error.empty()) return error;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.layout, 0, 2, sets, 0, nullptr);
  vkCmdDispatch(cmd, job.groups_x, job.groups_y, job.groups_z);
  // Make shader writes visible to the host mapping we read back from.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
  if (std::string error = submit_and_wait(d, objs, cmd); !error.empty()) return error;
  result->buffers.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    const auto* bytes = static_cast<const uint8_t*>(ssbos[i].mapped);
    result->buffers[i].assign(bytes, bytes + job.buffers[i].size());
  }
  return {};
}

}  // namespace

std::string vulkan_unavailable_reason() { return shared_device().error; }

std::vector<ComputeResult> vulkan_run(const SpirvProgram& program, const std::vector<ComputeJob>& jobs) {
  VulkanDevice& d = shared_device();
  std::vector<ComputeResult> results;
  auto fail = [&](std::string error) {
    results.emplace_back();
    results.back().device = d.name;
    results.back().error = std::move(error);
    return results;
  };
  if (!d.error.empty()) return fail("Vulkan unavailable: " + d.error);
  if (spirv_uses_float64(program.words) && !d.float64)
    return fail("shader uses double (Float64) but " + d.name + " lacks shaderFloat64");
  if (!program.uniform_blocks.empty() || !program.samplers.empty())
    return fail("compute jobs do not bind named uniform blocks or samplers yet (vertex/fragment jobs do): use "
                "loose uniforms and buffers");
  const auto n = static_cast<uint32_t>(jobs[0].buffers.size());
  if (n > d.limits.maxPerStageDescriptorStorageBuffers) return fail("too many buffers for " + d.name);
  std::lock_guard<std::mutex> lock(d.mu);
  JobObjects shared(d.device);
  Pipeline pipeline;
  if (std::string e = make_pipeline(d, program, n, shared, &pipeline); !e.empty()) return fail(e);
  for (const ComputeJob& job : jobs) {
    ComputeResult result;
    result.device = d.name;
    result.error = dispatch(d, program, pipeline, job, &result);
    result.ok = result.error.empty();
    if (!result.ok) result.buffers.clear();
    results.push_back(std::move(result));
    if (!results.back().ok) break;
  }
  return results;
}

}  // namespace doublet::runner::detail
