#include "gpu/resources.h"

#include <fmt/format.h>

#include <algorithm>

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

uint32_t fullMipCount(VkExtent3D extent) {
  uint32_t side = std::max({extent.width, extent.height, extent.depth}), levels = 1;
  while (side > 1) side /= 2, ++levels;
  return levels;
}

void Buffer::use(VkCommandBuffer cmd, const BufferUse& next) {
  if (readOnly(last_.access) && readOnly(next.access)) {
    // A read after reads: the last write was made visible to the earlier readers' stages and accesses
    // only. A read in another stage (or of another kind) chains one more dependency after them.
    if ((next.stage & ~last_.stage) || (next.access & ~last_.access))
      memoryBarrier(cmd, {last_.stage, VK_ACCESS_2_NONE}, next);
    last_.stage |= next.stage;
    last_.access |= next.access;
    return;
  }
  memoryBarrier(cmd, last_, next);
  last_ = next;
}

Image::Image(const Device& device, const ImageDesc& desc, const std::string& name) : desc_(desc), name_(name) {
  if (desc_.mips == 0) desc_.mips = fullMipCount(desc.extent);
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = desc.type;
  info.format = desc.format;
  // The two formats share a size class (the views reinterpret the same bits), which Vulkan allows
  // for a mutable image.
  if (desc.storageFormat != VK_FORMAT_UNDEFINED) info.flags |= VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
  info.extent = desc.extent;
  info.mipLevels = desc_.mips;
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

  const bool split = desc.storageFormat != VK_FORMAT_UNDEFINED;
  auto makeView = [&](uint32_t base, uint32_t count, const std::string& label, bool storage = false) {
    // With a storage format of its own, each view takes only its part of the usage: the main format
    // need not support storage.
    VkImageViewUsageCreateInfo usage{VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO};
    usage.usage = storage ? VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT) : desc.usage & ~VK_IMAGE_USAGE_STORAGE_BIT;
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    if (split) viewInfo.pNext = &usage;
    viewInfo.image = image;
    viewInfo.viewType = desc.type == VK_IMAGE_TYPE_3D ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = storage ? desc.storageFormat : desc.format;
    viewInfo.subresourceRange = {desc.aspect, base, count, 0, 1};
    VkImageView view;
    VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
    device.name(view, VK_OBJECT_TYPE_IMAGE_VIEW, label);
    return Unique<VkImageView>(device, view);
  };
  view_ = makeView(0, desc_.mips, name + " view");
  if (split) {
    if (desc_.mips != 1 || !(desc.usage & VK_IMAGE_USAGE_STORAGE_BIT))
      throw Error(fmt::format("{}: a storage format of its own needs one level and storage use", name));
    storageView_ = makeView(0, 1, name + " storage view", true);
    return;
  }
  if (desc_.mips > 1 && (desc.usage & VK_IMAGE_USAGE_STORAGE_BIT))
    for (uint32_t level = 0; level < desc_.mips; ++level)
      mipViews_.push_back(makeView(level, 1, fmt::format("{} mip {}", name, level)));
}

VkImageView Image::mipView(uint32_t level) const {
  if (mipViews_.empty()) {
    if (level != 0) throw Error(fmt::format("{} has no storage view of mip {}", name_, level));
    return view_;
  }
  return mipViews_.at(level);
}

void Image::use(VkCommandBuffer cmd, const ImageUse& next) {
  if (last_.layout == next.layout && readOnly(last_.access) && readOnly(next.access) &&
      last_.layout != VK_IMAGE_LAYOUT_UNDEFINED) {
    // A read after reads in the same layout: the last write (or layout change) was made visible to the
    // earlier readers only, so a read in another stage or of another kind chains one more dependency
    // after theirs; reads already covered need nothing.
    if ((next.stage & ~last_.stage) || (next.access & ~last_.access))
      transition(cmd, image_, {last_.stage, VK_ACCESS_2_NONE, last_.layout}, next, desc_.aspect);
    last_.stage |= next.stage;
    last_.access |= next.access;
    return;
  }
  transition(cmd, image_, last_, next, desc_.aspect);
  last_ = next;
}

void recordReadback(VkCommandBuffer cmd, Image& image, Buffer& buffer) {
  image.use(cmd, use::TransferSrc);
  buffer.use(cmd, use::TransferDstBuffer);
  VkBufferImageCopy region{};
  region.imageSubresource = {image.desc().aspect, 0, 0, 1};
  region.imageExtent = image.extent();
  vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), 1, &region);
  buffer.use(cmd, use::HostReadBuffer);
}

void generateMips(VkCommandBuffer cmd, Image& image, const ImageUse& after) {
  const uint32_t levels = image.desc().mips;
  image.use(cmd, use::TransferDst);
  auto size = [&](uint32_t level) {
    const VkExtent3D e = image.extent();
    return VkOffset3D{int32_t(std::max(1u, e.width >> level)), int32_t(std::max(1u, e.height >> level)),
                      int32_t(std::max(1u, e.depth >> level))};
  };
  for (uint32_t level = 1; level < levels; ++level) {
    // Level - 1 was just written (by the upload or the previous blit): read it from here on.
    transition(cmd, image.handle(), use::TransferDst, use::TransferSrc, image.desc().aspect, level - 1, 1);
    VkImageBlit2 region{VK_STRUCTURE_TYPE_IMAGE_BLIT_2};
    region.srcSubresource = {image.desc().aspect, level - 1, 0, 1};
    region.srcOffsets[1] = size(level - 1);
    region.dstSubresource = {image.desc().aspect, level, 0, 1};
    region.dstOffsets[1] = size(level);
    VkBlitImageInfo2 info{VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2};
    info.srcImage = info.dstImage = image.handle();
    info.srcImageLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    info.dstImageLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    info.regionCount = 1;
    info.pRegions = &region;
    info.filter = VK_FILTER_LINEAR;
    vkCmdBlitImage2(cmd, &info);
  }
  // All but the last level are now sources; bring every level to one state, then to `after`.
  transition(cmd, image.handle(), use::TransferDst, use::TransferSrc, image.desc().aspect, levels - 1, 1);
  image.assumeUse(use::TransferSrc);
  image.use(cmd, after);
}

void checkImageSize(const Device& device, VkExtent2D extent) {
  const uint32_t limit = device.limits().maxImageDimension2D;
  if (extent.width == 0 || extent.height == 0 || extent.width > limit || extent.height > limit)
    throw Error(fmt::format("Image size {}x{} is outside what {} supports (1 to {} per side).", extent.width,
                            extent.height, device.properties().deviceName, limit));
}

}  // namespace vitrine::gpu
