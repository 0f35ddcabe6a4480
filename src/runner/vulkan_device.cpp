// The lavapipe device shared by the Vulkan compute and graphics backends, and helpers for the
// objects every job creates (host-visible buffers, the global uniform block).
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "runner/vulkan_device.hpp"

namespace doublet::runner::detail {
namespace {

const char* result_name(VkResult r) {
  switch (r) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
    default: return "VkResult(other)";
  }
}

}  // namespace

std::string vk_failed(const char* call, VkResult r) {
  return std::string(call) + " failed: " + result_name(r) + " (" + std::to_string(static_cast<int>(r)) + ")";
}

std::string begin_one_time_commands(VulkanDevice& d, VkCommandPool pool, JobObjects& job, VkCommandBuffer* out) {
  VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  cbai.commandPool = pool;
  cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cbai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  if (VkResult r = vkAllocateCommandBuffers(d.device, &cbai, &cmd); r != VK_SUCCESS)
    return vk_failed("vkAllocateCommandBuffers", r);
  job.cleanup.push_back([&d, pool, cmd] { vkFreeCommandBuffers(d.device, pool, 1, &cmd); });
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (VkResult r = vkBeginCommandBuffer(cmd, &begin); r != VK_SUCCESS) return vk_failed("vkBeginCommandBuffer", r);
  *out = cmd;
  return {};
}

std::string submit_and_wait(VulkanDevice& d, JobObjects& job, VkCommandBuffer cmd) {
  if (VkResult r = vkEndCommandBuffer(cmd); r != VK_SUCCESS) return vk_failed("vkEndCommandBuffer", r);
  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VkFence fence;
  if (VkResult r = vkCreateFence(d.device, &fci, nullptr, &fence); r != VK_SUCCESS) return vk_failed("vkCreateFence", r);
  job.cleanup.push_back([&d, fence] { vkDestroyFence(d.device, fence, nullptr); });
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  if (VkResult r = vkQueueSubmit(d.queue, 1, &submit, fence); r != VK_SUCCESS) return vk_failed("vkQueueSubmit", r);
  if (VkResult r = vkWaitForFences(d.device, 1, &fence, VK_TRUE, 300ull * 1000 * 1000 * 1000); r != VK_SUCCESS) {
    vkQueueWaitIdle(d.queue);  // never free objects the queue may still use
    return vk_failed("vkWaitForFences (300 s)", r);
  }
  return {};
}

namespace {

const char* const kLavapipeIcd = "/usr/share/vulkan/icd.d/lvp_icd.x86_64.json";

// Creates an instance and returns the lavapipe physical device, or an explanation.
std::string find_lavapipe(VulkanDevice& d) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "doublet_runner";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  if (VkResult r = vkCreateInstance(&ici, nullptr, &d.instance); r != VK_SUCCESS) {
    d.instance = VK_NULL_HANDLE;
    return vk_failed("vkCreateInstance", r);
  }
  uint32_t count = 0;
  // An ICD for absent hardware may fail here; the loader then reports an error for the whole call.
  VkResult r = vkEnumeratePhysicalDevices(d.instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  if (r == VK_SUCCESS || r == VK_INCOMPLETE) r = vkEnumeratePhysicalDevices(d.instance, &count, devices.data());
  if (r != VK_SUCCESS && r != VK_INCOMPLETE) return vk_failed("vkEnumeratePhysicalDevices", r);
  std::string seen;
  for (uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(devices[i], &p);
    seen += std::string(seen.empty() ? "" : ", ") + p.deviceName;
    if (p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU || std::strstr(p.deviceName, "llvmpipe")) {
      if (p.apiVersion < VK_API_VERSION_1_1) return std::string(p.deviceName) + " supports only Vulkan 1.0";
      d.physical = devices[i];
      d.name = p.deviceName;
      d.limits = p.limits;
      return {};
    }
  }
  return "no lavapipe (CPU) Vulkan device among [" + seen + "]";
}

std::string init(VulkanDevice& d) {
  std::string why = find_lavapipe(d);
  // Other ICDs (hardware drivers without their hardware) can break instance creation or
  // enumeration. Unless the user chose ICDs, retry with lavapipe alone.
  if (!why.empty() && !std::getenv("VK_ICD_FILENAMES") && !std::getenv("VK_DRIVER_FILES") &&
      std::filesystem::exists(kLavapipeIcd)) {
    if (d.instance) vkDestroyInstance(d.instance, nullptr);
    d.instance = VK_NULL_HANDLE;
    setenv("VK_ICD_FILENAMES", kLavapipeIcd, 0);
    std::string again = find_lavapipe(d);
    if (!again.empty()) why += "; with VK_ICD_FILENAMES=" + std::string(kLavapipeIcd) + ": " + again;
    else why.clear();
  }
  if (!why.empty()) return why;

  uint32_t nfam = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(d.physical, &nfam, nullptr);
  std::vector<VkQueueFamilyProperties> fams(nfam);
  vkGetPhysicalDeviceQueueFamilyProperties(d.physical, &nfam, fams.data());
  d.queue_family = UINT32_MAX;
  // Prefer a family that also draws (lavapipe's only family does): graphics jobs share the queue.
  for (uint32_t i = 0; i < nfam && d.queue_family == UINT32_MAX; ++i)
    if ((fams[i].queueFlags & (VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT)) == (VK_QUEUE_COMPUTE_BIT | VK_QUEUE_GRAPHICS_BIT))
      d.queue_family = i;
  d.graphics = d.queue_family != UINT32_MAX;
  for (uint32_t i = 0; i < nfam && d.queue_family == UINT32_MAX; ++i)
    if (fams[i].queueFlags & VK_QUEUE_COMPUTE_BIT) d.queue_family = i;
  if (d.queue_family == UINT32_MAX) return d.name + " has no compute queue";

  VkPhysicalDeviceFeatures supported;
  vkGetPhysicalDeviceFeatures(d.physical, &supported);
  VkPhysicalDeviceFeatures enabled{};
  enabled.shaderFloat64 = supported.shaderFloat64;  // native doubles: the reference for lowered code
  enabled.shaderInt64 = supported.shaderInt64;
  d.float64 = supported.shaderFloat64 == VK_TRUE;
  // Graphics jobs read inputs from and write outputs to storage buffers in the vertex and fragment stages.
  enabled.vertexPipelineStoresAndAtomics = supported.vertexPipelineStoresAndAtomics;
  enabled.fragmentStoresAndAtomics = supported.fragmentStoresAndAtomics;
  d.stage_stores = supported.vertexPipelineStoresAndAtomics && supported.fragmentStoresAndAtomics;
  enabled.geometryShader = supported.geometryShader;  // geometry jobs (runner.hpp)
  d.geometry = supported.geometryShader == VK_TRUE;
  enabled.tessellationShader = supported.tessellationShader;  // tessellation jobs
  d.tessellation = supported.tessellationShader == VK_TRUE;

  float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = d.queue_family;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.pEnabledFeatures = &enabled;
  if (VkResult r = vkCreateDevice(d.physical, &dci, nullptr, &d.device); r != VK_SUCCESS)
    return vk_failed("vkCreateDevice", r);
  vkGetDeviceQueue(d.device, d.queue_family, 0, &d.queue);
  vkGetPhysicalDeviceMemoryProperties(d.physical, &d.memory);
  return {};
}

}  // namespace

VulkanDevice& shared_device() {
  static VulkanDevice* d = [] {
    auto* dev = new VulkanDevice;
    dev->error = init(*dev);
    return dev;
  }();
  return *d;
}

std::string allocate_memory(VulkanDevice& d, JobObjects& job, const VkMemoryRequirements& req,
                            VkMemoryPropertyFlags flags, VkDeviceMemory* out) {
  uint32_t type = UINT32_MAX;
  for (uint32_t i = 0; i < d.memory.memoryTypeCount && type == UINT32_MAX; ++i)
    if ((req.memoryTypeBits & (1u << i)) && (d.memory.memoryTypes[i].propertyFlags & flags) == flags) type = i;
  if (type == UINT32_MAX) return "no memory type with the needed properties on " + d.name;
  VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = type;
  if (VkResult r = vkAllocateMemory(d.device, &mai, nullptr, out); r != VK_SUCCESS) return vk_failed("vkAllocateMemory", r);
  job.cleanup.push_back([&d, mem = *out] { vkFreeMemory(d.device, mem, nullptr); });
  return {};
}

std::string make_buffer(VulkanDevice& d, JobObjects& job, VkBufferUsageFlags usage, const std::vector<uint8_t>& data,
                        HostBuffer* out) {
  VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bci.size = std::max<VkDeviceSize>(data.size(), 16);  // Vulkan forbids empty buffers
  bci.usage = usage;
  bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (VkResult r = vkCreateBuffer(d.device, &bci, nullptr, &out->buffer); r != VK_SUCCESS)
    return vk_failed("vkCreateBuffer", r);
  VkBuffer buf = out->buffer;
  job.cleanup.push_back([&d, buf] { vkDestroyBuffer(d.device, buf, nullptr); });

  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(d.device, buf, &req);
  VkDeviceMemory mem;
  if (std::string e = allocate_memory(d, job, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, &mem);
      !e.empty())
    return e;
  if (VkResult r = vkBindBufferMemory(d.device, buf, mem, 0); r != VK_SUCCESS) return vk_failed("vkBindBufferMemory", r);
  if (VkResult r = vkMapMemory(d.device, mem, 0, VK_WHOLE_SIZE, 0, &out->mapped); r != VK_SUCCESS)
    return vk_failed("vkMapMemory", r);
  std::memset(out->mapped, 0, bci.size);
  if (!data.empty()) std::memcpy(out->mapped, data.data(), data.size());
  return {};
}

void store_scalar(uint8_t* at, char scalar, double value) {
  switch (scalar) {
    case 'd': std::memcpy(at, &value, 8); break;
    case 'f': { const float f = static_cast<float>(value); std::memcpy(at, &f, 4); break; }
    case 'i': { const int32_t i = static_cast<int32_t>(value); std::memcpy(at, &i, 4); break; }
    case 'b': { const uint32_t b = value != 0; std::memcpy(at, &b, 4); break; }
    default: { const uint32_t u = static_cast<uint32_t>(value); std::memcpy(at, &u, 4); break; }
  }
}

std::string uniform_block_bytes(const SpirvProgram& program, const std::map<std::string, float>& float_uniforms,
                                const std::map<std::string, std::vector<double>>& uniforms, std::vector<uint8_t>* bytes) {
  bytes->assign(std::max<uint32_t>(program.uniform_block_size, 16), 0);
  for (const auto& [name, value] : float_uniforms) {
    auto it = program.uniforms.find(name);
    if (it == program.uniforms.end()) continue;  // inactive or absent: GL ignores it too
    if (!it->second.is_float) return "uniform '" + name + "' is not a float; float_uniforms can only set floats";
    if (it->second.offset + sizeof(float) > bytes->size()) return "uniform '" + name + "' lies outside its block";
    std::memcpy(bytes->data() + it->second.offset, &value, sizeof(float));
  }
  for (const auto& [name, values] : uniforms) {
    auto it = program.uniforms.find(name);
    if (it == program.uniforms.end()) continue;
    const UniformSlot& slot = it->second;
    if (slot.components == 0) return "uniform '" + name + "' is not a scalar, vector or matrix";
    if (static_cast<int>(values.size()) != slot.components)
      return "uniform '" + name + "' has " + std::to_string(slot.components) + " component(s), job gives " +
             std::to_string(values.size());
    const size_t width = slot.is_double ? sizeof(double) : sizeof(float);
    const size_t rows = values.size() / static_cast<size_t>(slot.columns);
    // std140: vector components are packed; matrix columns start at vec4 (dvec3/dvec4: 32-byte) strides.
    const size_t column_stride = slot.columns == 1 ? 0 : std140_column_stride(slot.is_double, static_cast<int>(rows));
    for (size_t c = 0; c < values.size(); ++c) {
      const size_t at = slot.offset + (c / rows) * column_stride + (c % rows) * width;
      if (at + width > bytes->size()) return "uniform '" + name + "' lies outside its block";
      store_scalar(bytes->data() + at, slot.scalar, values[c]);
    }
  }
  return {};
}

}  // namespace doublet::runner::detail
