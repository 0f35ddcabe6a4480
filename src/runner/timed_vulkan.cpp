// Vulkan half of run_compute_timed: the command buffer brackets the dispatch with two
// vkCmdWriteTimestamp and is re-submitted for every repetition, so each sample is device time of
// the dispatch alone (no compile, no upload, no submit overhead).
#include <vulkan/vulkan.h>

#include <chrono>
#include <mutex>

#include "runner/timed_compute.hpp"
#include "runner/vulkan_device.hpp"

namespace doublet::runner::detail {
namespace {

#define DOUBLET_VK(call)                                          \
  do {                                                            \
    if (VkResult r_ = (call); r_ != VK_SUCCESS) return vk_failed(#call, r_); \
  } while (0)

// The device's timestamp tick in seconds, or 0 when the compute queue cannot write timestamps.
double timestamp_tick(VulkanDevice& d) {
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(d.physical, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(d.physical, &n, families.data());
  if (d.queue_family >= n || families[d.queue_family].timestampValidBits == 0) return 0;
  return d.limits.timestampPeriod * 1e-9;
}

std::string run(VulkanDevice& d, const SpirvProgram& program, const ComputeJob& job, int warmup, int reps,
                std::chrono::steady_clock::time_point start, TimedResult* out) {
  JobObjects objs(d.device);
  const auto n = static_cast<uint32_t>(job.buffers.size());
  for (int b : program.ssbo_bindings)  // an unbound SSBO would be read through a null descriptor
    if (b < 0 || static_cast<uint32_t>(b) >= n)
      return "shader declares an SSBO at binding " + std::to_string(b) + " but the job has " + std::to_string(n) +
             " buffer(s)";
  // Layouts as the functional backend: set 0 holds SSBO i at binding i, set 1 the uniform block.
  std::vector<VkDescriptorSetLayoutBinding> ssbo(n);
  for (uint32_t i = 0; i < n; ++i) ssbo[i] = {i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutBinding ubo_binding{kUniformBinding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1,
                                           VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayout layouts[2];
  for (int s = 0; s < 2; ++s) {
    VkDescriptorSetLayoutCreateInfo lci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    lci.bindingCount = s == 0 ? n : 1;
    lci.pBindings = s == 0 ? ssbo.data() : &ubo_binding;
    DOUBLET_VK(vkCreateDescriptorSetLayout(d.device, &lci, nullptr, &layouts[s]));
    VkDescriptorSetLayout l = layouts[s];
    objs.cleanup.push_back([&d, l] { vkDestroyDescriptorSetLayout(d.device, l, nullptr); });
  }
  VkPipelineLayoutCreateInfo plci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  plci.setLayoutCount = 2;
  plci.pSetLayouts = layouts;
  VkPipelineLayout layout;
  DOUBLET_VK(vkCreatePipelineLayout(d.device, &plci, nullptr, &layout));
  objs.cleanup.push_back([&d, layout] { vkDestroyPipelineLayout(d.device, layout, nullptr); });
  VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  smci.codeSize = program.words.size() * sizeof(uint32_t);
  smci.pCode = program.words.data();
  VkShaderModule module;
  DOUBLET_VK(vkCreateShaderModule(d.device, &smci, nullptr, &module));
  objs.cleanup.push_back([&d, module] { vkDestroyShaderModule(d.device, module, nullptr); });
  VkComputePipelineCreateInfo cpci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  cpci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  cpci.stage.module = module;
  cpci.stage.pName = "main";
  cpci.layout = layout;
  VkPipeline pipeline;
  DOUBLET_VK(vkCreateComputePipelines(d.device, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipeline));
  objs.cleanup.push_back([&d, pipeline] { vkDestroyPipeline(d.device, pipeline, nullptr); });

  std::vector<HostBuffer> buffers(n + 1);
  for (uint32_t i = 0; i < n; ++i)
    if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, job.buffers[i], &buffers[i]); !e.empty())
      return e;
  std::vector<uint8_t> ubo_bytes;
  if (std::string e = uniform_block_bytes(program, job.float_uniforms, job.uniforms, &ubo_bytes); !e.empty()) return e;
  if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, ubo_bytes, &buffers[n]); !e.empty())
    return e;

  std::vector<VkDescriptorPoolSize> sizes{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1}};
  if (n) sizes.push_back({VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, n});
  VkDescriptorPoolCreateInfo dpci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  dpci.maxSets = 2;
  dpci.poolSizeCount = static_cast<uint32_t>(sizes.size());
  dpci.pPoolSizes = sizes.data();
  VkDescriptorPool pool;
  DOUBLET_VK(vkCreateDescriptorPool(d.device, &dpci, nullptr, &pool));
  objs.cleanup.push_back([&d, pool] { vkDestroyDescriptorPool(d.device, pool, nullptr); });
  VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  dsai.descriptorPool = pool;
  dsai.descriptorSetCount = 2;
  dsai.pSetLayouts = layouts;
  VkDescriptorSet sets[2];
  DOUBLET_VK(vkAllocateDescriptorSets(d.device, &dsai, sets));
  std::vector<VkDescriptorBufferInfo> infos(n + 1);
  std::vector<VkWriteDescriptorSet> writes(n + 1);
  for (uint32_t i = 0; i <= n; ++i) {
    const bool is_ubo = i == n;
    infos[i] = {buffers[i].buffer, 0, VK_WHOLE_SIZE};
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = sets[is_ubo ? 1 : 0];
    writes[i].dstBinding = is_ubo ? kUniformBinding : i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = is_ubo ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &infos[i];
  }
  vkUpdateDescriptorSets(d.device, n + 1, writes.data(), 0, nullptr);

  const double tick = timestamp_tick(d);
  VkQueryPool queries = VK_NULL_HANDLE;
  if (tick > 0) {
    VkQueryPoolCreateInfo qpci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qpci.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qpci.queryCount = 2;
    DOUBLET_VK(vkCreateQueryPool(d.device, &qpci, nullptr, &queries));
    objs.cleanup.push_back([&d, queries] { vkDestroyQueryPool(d.device, queries, nullptr); });
  }
  out->clock = tick > 0 ? "vkCmdWriteTimestamp" : "fence-bracketed CPU time";

  VkCommandPoolCreateInfo cpool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  cpool.queueFamilyIndex = d.queue_family;
  VkCommandPool cmd_pool;
  DOUBLET_VK(vkCreateCommandPool(d.device, &cpool, nullptr, &cmd_pool));
  objs.cleanup.push_back([&d, cmd_pool] { vkDestroyCommandPool(d.device, cmd_pool, nullptr); });
  VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cbai.commandPool = cmd_pool;
  cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cbai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  DOUBLET_VK(vkAllocateCommandBuffers(d.device, &cbai, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};  // re-submitted: not one-time
  DOUBLET_VK(vkBeginCommandBuffer(cmd, &begin));
  if (queries) vkCmdResetQueryPool(cmd, queries, 0, 2);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 2, sets, 0, nullptr);
  if (queries) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queries, 0);
  vkCmdDispatch(cmd, job.groups_x, job.groups_y, job.groups_z);
  if (queries) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queries, 1);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
  DOUBLET_VK(vkEndCommandBuffer(cmd));

  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence;
  DOUBLET_VK(vkCreateFence(d.device, &fci, nullptr, &fence));
  objs.cleanup.push_back([&d, fence] { vkDestroyFence(d.device, fence, nullptr); });
  for (int rep = 0; rep < warmup + reps; ++rep) {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    const auto t0 = std::chrono::steady_clock::now();
    DOUBLET_VK(vkQueueSubmit(d.queue, 1, &submit, fence));
    if (VkResult r = vkWaitForFences(d.device, 1, &fence, VK_TRUE, 300ull * 1000 * 1000 * 1000); r != VK_SUCCESS) {
      vkQueueWaitIdle(d.queue);  // never free objects the queue may still use
      return vk_failed("vkWaitForFences (300 s)", r);
    }
    const auto done = std::chrono::steady_clock::now();
    const double cpu = std::chrono::duration<double>(done - t0).count();
    if (rep == 0) out->first_result_seconds = std::chrono::duration<double>(done - start).count();
    DOUBLET_VK(vkResetFences(d.device, 1, &fence));
    double seconds = cpu;
    if (queries) {
      uint64_t stamps[2] = {};
      DOUBLET_VK(vkGetQueryPoolResults(d.device, queries, 0, 2, sizeof stamps, stamps, sizeof(uint64_t),
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
      seconds = static_cast<double>(stamps[1] - stamps[0]) * tick;
    }
    if (rep >= warmup) out->seconds.push_back(seconds);
  }
  out->buffers.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    const auto* bytes = static_cast<const uint8_t*>(buffers[i].mapped);
    out->buffers[i].assign(bytes, bytes + job.buffers[i].size());
  }
  return {};
}

}  // namespace

TimedResult vulkan_run_timed(const SpirvProgram& program, const ComputeJob& job, int warmup, int repetitions,
                             std::chrono::steady_clock::time_point start) {
  VulkanDevice& d = shared_device();
  TimedResult r;
  r.device = d.name;
  if (!d.error.empty()) {
    r.error = "Vulkan unavailable: " + d.error;
    return r;
  }
  if (spirv_uses_float64(program.words) && !d.float64) {
    r.error = "shader uses double (Float64) but " + d.name + " lacks shaderFloat64";
    return r;
  }
  std::lock_guard<std::mutex> lock(d.mu);
  r.error = run(d, program, job, warmup, repetitions, start, &r);
  r.ok = r.error.empty();
  return r;
}

}  // namespace doublet::runner::detail
