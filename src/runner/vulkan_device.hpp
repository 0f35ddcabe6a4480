// The lavapipe device shared by the Vulkan backends (compute, graphics) and per-job helpers.
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "runner/internal.hpp"

namespace doublet::runner::detail {

struct VulkanDevice {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queue_family = 0;
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceLimits limits{};
  bool float64 = false;
  bool graphics = false;      // the queue draws as well as dispatches
  bool geometry = false;  // geometryShader enabled
  bool tessellation = false;  // tessellationShader enabled
  bool stage_stores = false;  // vertexPipelineStoresAndAtomics and fragmentStoresAndAtomics enabled
  std::string name;
  std::string error;  // non-empty: this backend is unusable, and why
  std::mutex mu;      // the queue and per-job pools are externally synchronised objects
};

// Created on first use, never destroyed: tearing down a driver during static destruction only
// invites exit-time crashes.
VulkanDevice& shared_device();

std::string vk_failed(const char* call, VkResult r);

// Everything one job creates; destroyed in reverse order whatever happens.
struct JobObjects {
  VkDevice dev;
  std::vector<std::function<void()>> cleanup;
  explicit JobObjects(VkDevice d) : dev(d) {}
  ~JobObjects() {
    for (auto it = cleanup.rbegin(); it != cleanup.rend(); ++it) (*it)();
  }
};

struct HostBuffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

// Memory for `req` from the first type it allows that has every bit of `flags`, freed with `job`.
std::string allocate_memory(VulkanDevice& d, JobObjects& job, const VkMemoryRequirements& req,
                            VkMemoryPropertyFlags flags, VkDeviceMemory* out);

// A host-visible, coherent buffer holding `data` (zero-padded to at least 16 bytes), mapped.
std::string make_buffer(VulkanDevice& d, JobObjects& job, VkBufferUsageFlags usage, const std::vector<uint8_t>& data,
                        HostBuffer* out);

// A primary command buffer from `pool`, begun for one submission, freed with `job`.
std::string begin_one_time_commands(VulkanDevice& d, VkCommandPool pool, JobObjects& job, VkCommandBuffer* out);

// Ends `cmd`, submits it and waits for it (300 s at most); if the wait fails, waits for the
// queue to drain first, because `job`'s objects must not be freed while in use.
std::string submit_and_wait(VulkanDevice& d, JobObjects& job, VkCommandBuffer cmd);

// The runner's test texture (runner.hpp) as a sampled image, uploaded with a command from `pool`.
struct SampledTexture {
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};
std::string make_test_texture(VulkanDevice& d, JobObjects& objs, VkCommandPool pool, TextureKind kind,
                              SampledTexture* out);

// The global uniform block's bytes: zero everywhere, then each named value at its reflected offset.
std::string uniform_block_bytes(const SpirvProgram& program, const std::map<std::string, float>& float_uniforms,
                                const std::map<std::string, std::vector<double>>& uniforms, std::vector<uint8_t>* bytes);

}  // namespace doublet::runner::detail
