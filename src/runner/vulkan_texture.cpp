// The runner's test texture (runner.hpp, test_texture) as a sampled Vulkan image: uploaded once
// per batch through a staging buffer, read with NEAREST filtering like the GLES backend's copy.
#include <vulkan/vulkan.h>

#include <cstring>

#include "runner/vulkan_device.hpp"

namespace doublet::runner::detail {
namespace {

void transition(VkCommandBuffer cmd, VkImage image, uint32_t layers, VkImageLayout from, VkImageLayout to,
                VkAccessFlags src_access, VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

std::string make_image(VulkanDevice& d, JobObjects& objs, TextureKind kind, uint32_t layers, VkImage* out) {
  VkImageCreateInfo ici{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ici.flags = kind == TextureKind::Cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
  ici.imageType = kind == TextureKind::Tex3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  ici.format = VK_FORMAT_R32G32B32A32_SFLOAT;
  ici.extent = {kTextureSize, kTextureSize, kind == TextureKind::Tex3D ? kTextureSize : 1};
  ici.mipLevels = 1;
  ici.arrayLayers = layers;
  ici.samples = VK_SAMPLE_COUNT_1_BIT;
  ici.tiling = VK_IMAGE_TILING_OPTIMAL;
  ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  ici.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (VkResult r = vkCreateImage(d.device, &ici, nullptr, out); r != VK_SUCCESS) return vk_failed("vkCreateImage", r);
  VkImage image = *out;
  objs.cleanup.push_back([&d, image] { vkDestroyImage(d.device, image, nullptr); });
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(d.device, image, &req);
  VkDeviceMemory mem;
  if (std::string e = allocate_memory(d, objs, req, 0, &mem); !e.empty()) return e;
  if (VkResult r = vkBindImageMemory(d.device, image, mem, 0); r != VK_SUCCESS) return vk_failed("vkBindImageMemory", r);
  return {};
}

}  // namespace

std::string make_test_texture(VulkanDevice& d, JobObjects& objs, VkCommandPool pool, TextureKind kind,
                              SampledTexture* out) {
  const uint32_t layers = kind == TextureKind::Cube ? 6 : 1;
  const std::vector<float> texels = test_texture(kind);
  std::vector<uint8_t> bytes(texels.size() * sizeof(float));
  std::memcpy(bytes.data(), texels.data(), bytes.size());
  HostBuffer staging;
  if (std::string e = make_buffer(d, objs, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, bytes, &staging); !e.empty()) return e;
  VkImage image;
  if (std::string e = make_image(d, objs, kind, layers, &image); !e.empty()) return e;

  VkCommandBuffer cmd;
  if (std::string e = begin_one_time_commands(d, pool, objs, &cmd); !e.empty()) return e;
  transition(cmd, image, layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
             VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers};
  region.imageExtent = {kTextureSize, kTextureSize, kind == TextureKind::Tex3D ? kTextureSize : 1};
  vkCmdCopyBufferToImage(cmd, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  transition(cmd, image, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
             VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
             VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  if (std::string e = submit_and_wait(d, objs, cmd); !e.empty()) return e;

  VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vci.image = image;
  vci.viewType = kind == TextureKind::Tex3D ? VK_IMAGE_VIEW_TYPE_3D
                 : kind == TextureKind::Cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
  vci.format = VK_FORMAT_R32G32B32A32_SFLOAT;
  vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
  if (VkResult r = vkCreateImageView(d.device, &vci, nullptr, &out->view); r != VK_SUCCESS)
    return vk_failed("vkCreateImageView", r);
  VkImageView view = out->view;
  objs.cleanup.push_back([&d, view] { vkDestroyImageView(d.device, view, nullptr); });

  VkSamplerCreateInfo sci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  sci.magFilter = sci.minFilter = VK_FILTER_NEAREST;
  sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  const VkSamplerAddressMode wrap =
      kind == TextureKind::Cube ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
  sci.addressModeU = sci.addressModeV = sci.addressModeW = wrap;
  sci.maxLod = 0;
  if (VkResult r = vkCreateSampler(d.device, &sci, nullptr, &out->sampler); r != VK_SUCCESS)
    return vk_failed("vkCreateSampler", r);
  VkSampler sampler = out->sampler;
  objs.cleanup.push_back([&d, sampler] { vkDestroySampler(d.device, sampler, nullptr); });
  return {};
}

}  // namespace doublet::runner::detail
