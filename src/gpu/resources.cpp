#include "gpu/resources.h"

#include <fmt/format.h>

#include "gpu/barriers.h"
#include "gpu/check.h"

namespace vitrine::gpu {

Buffer::Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
               const std::string& name)
    : device_(&device), size_(size) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer;
  VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
  buffer_ = Unique<VkBuffer>(device, buffer);

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  constexpr VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
  switch (use) {
    case MemoryUse::Device:
      memory_ = device.allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
      break;
    case MemoryUse::Upload:  // prefer memory the GPU reads fast (resizable BAR), else any coherent
      memory_ = device.allocate(requirements,
                                host | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                                host | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
      break;
    case MemoryUse::Readback:
      memory_ = device.allocate(requirements, host | VK_MEMORY_PROPERTY_HOST_CACHED_BIT, host);
      break;
  }
  VK_CHECK(vkBindBufferMemory(device, buffer, memory_, 0));
  if (use != MemoryUse::Device) VK_CHECK(vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  device.name(buffer, VK_OBJECT_TYPE_BUFFER, name);
  device.name(VkDeviceMemory(memory_), VK_OBJECT_TYPE_DEVICE_MEMORY, name + " memory");
}

void Buffer::invalidate() const {
  if (!mapped_) return;
  const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, memory_, 0, VK_WHOLE_SIZE};
  VK_CHECK(vkInvalidateMappedMemoryRanges(*device_, 1, &range));
}

Image::Image(const Device& device, const ImageDesc& desc, const std::string& name) : desc_(desc) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = desc.type;
  info.format = desc.format;
  info.extent = desc.extent;
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = desc.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  image_ = Unique<VkImage>(device, image);

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device, image, &requirements);
  memory_ = device.allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  VK_CHECK(vkBindImageMemory(device, image, memory_, 0));

  constexpr VkImageUsageFlags viewable = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                         VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  device.name(image, VK_OBJECT_TYPE_IMAGE, name);
  device.name(VkDeviceMemory(memory_), VK_OBJECT_TYPE_DEVICE_MEMORY, name + " memory");
  if (!(desc.usage & viewable)) return;  // copy-only images have no view

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = desc.type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = desc.format;
  viewInfo.subresourceRange = {desc.aspect, 0, 1, 0, 1};
  VkImageView view;
  VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
  view_ = Unique<VkImageView>(device, view);
  device.name(view, VK_OBJECT_TYPE_IMAGE_VIEW, name + " view");
}

void recordReadback(VkCommandBuffer cmd, const Image& image, const Buffer& buffer) {
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {image.desc().extent.width, image.desc().extent.height, 1};
  vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), 1, &region);
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_HOST_BIT,
                VK_ACCESS_2_HOST_READ_BIT);
}

void checkImageSize(const Device& device, VkExtent2D extent) {
  const uint32_t limit = device.limits().maxImageDimension2D;
  if (extent.width == 0 || extent.height == 0 || extent.width > limit || extent.height > limit)
    throw Error(fmt::format("Image size {}x{} is outside what {} supports (1 to {} per side).", extent.width,
                            extent.height, device.properties().deviceName, limit));
}

}  // namespace vitrine::gpu
