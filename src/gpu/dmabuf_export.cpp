#include "gpu/dmabuf_export.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>

#include "gpu/check.h"

namespace vitrine::gpu {
namespace {

// Each memory plane's aspect, for vkGetImageSubresourceLayout on an image with a DRM modifier.
constexpr std::array<VkImageAspectFlagBits, 4> kDrmMemoryPlanes{
    VK_IMAGE_ASPECT_MEMORY_PLANE_0_BIT_EXT, VK_IMAGE_ASPECT_MEMORY_PLANE_1_BIT_EXT,
    VK_IMAGE_ASPECT_MEMORY_PLANE_2_BIT_EXT, VK_IMAGE_ASPECT_MEMORY_PLANE_3_BIT_EXT};

std::vector<VkDrmFormatModifierPropertiesEXT> drmModifierList(VkPhysicalDevice physical, VkFormat format) {
  VkDrmFormatModifierPropertiesListEXT list{VK_STRUCTURE_TYPE_DRM_FORMAT_MODIFIER_PROPERTIES_LIST_EXT};
  VkFormatProperties2 properties{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2, &list};
  vkGetPhysicalDeviceFormatProperties2(physical, format, &properties);
  std::vector<VkDrmFormatModifierPropertiesEXT> modifiers(list.drmFormatModifierCount);
  list.pDrmFormatModifierProperties = modifiers.data();
  vkGetPhysicalDeviceFormatProperties2(physical, format, &properties);
  modifiers.resize(list.drmFormatModifierCount);
  return modifiers;
}

// Whether an image of `format` with `modifier` can be made for `usage` with exportable DMA-BUF memory.
bool exportableWith(VkPhysicalDevice physical, VkFormat format, VkImageUsageFlags usage, uint64_t modifier) {
  VkPhysicalDeviceImageDrmFormatModifierInfoEXT modifierInfo{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_IMAGE_DRM_FORMAT_MODIFIER_INFO_EXT};
  modifierInfo.drmFormatModifier = modifier;
  modifierInfo.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkPhysicalDeviceExternalImageFormatInfo external{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_IMAGE_FORMAT_INFO,
                                                   &modifierInfo};
  external.handleType = VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT;
  VkPhysicalDeviceImageFormatInfo2 info{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_IMAGE_FORMAT_INFO_2, &external};
  info.format = format;
  info.type = VK_IMAGE_TYPE_2D;
  info.tiling = VK_IMAGE_TILING_DRM_FORMAT_MODIFIER_EXT;
  info.usage = usage;
  VkExternalImageFormatProperties externalProperties{VK_STRUCTURE_TYPE_EXTERNAL_IMAGE_FORMAT_PROPERTIES};
  VkImageFormatProperties2 properties{VK_STRUCTURE_TYPE_IMAGE_FORMAT_PROPERTIES_2, &externalProperties};
  if (vkGetPhysicalDeviceImageFormatProperties2(physical, &info, &properties) != VK_SUCCESS) return false;
  return externalProperties.externalMemoryProperties.externalMemoryFeatures &
         VK_EXTERNAL_MEMORY_FEATURE_EXPORTABLE_BIT;
}

}  // namespace

FileDescriptor& FileDescriptor::operator=(FileDescriptor&& other) noexcept {
  if (this != &other) {
    reset();
    fd_ = std::exchange(other.fd_, -1);
  }
  return *this;
}

void FileDescriptor::reset() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

std::vector<drm::DriverModifier> exportableModifiers(const Device& device, VkFormat format, VkImageUsageFlags usage,
                                                     VkFormatFeatureFlags features) {
  std::vector<drm::DriverModifier> found;
  if (!device.exportsDmaBuf()) return found;
  for (const auto& entry : drmModifierList(device.physical(), format)) {
    if ((entry.drmFormatModifierTilingFeatures & features) != features) continue;
    if (entry.drmFormatModifierPlaneCount == 0 || entry.drmFormatModifierPlaneCount > kDrmMemoryPlanes.size()) continue;
    if (!exportableWith(device.physical(), format, usage, entry.drmFormatModifier)) continue;
    found.push_back({entry.drmFormatModifier, entry.drmFormatModifierPlaneCount});
  }
  return found;
}

ExportedImage::ExportedImage(const Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
                             std::span<const uint64_t> modifiers, const std::string& name)
    : format_(format), extent_(extent) {
  if (!device.exportsDmaBuf()) throw Error("the device cannot export DMA-BUFs");
  if (modifiers.empty()) throw Error("no DRM format modifier to make the image with");
  const std::vector<uint64_t> list(modifiers.begin(), modifiers.end());
  VkImageDrmFormatModifierListCreateInfoEXT modifierList{
      VK_STRUCTURE_TYPE_IMAGE_DRM_FORMAT_MODIFIER_LIST_CREATE_INFO_EXT};
  modifierList.drmFormatModifierCount = uint32_t(list.size());
  modifierList.pDrmFormatModifiers = list.data();
  VkExternalMemoryImageCreateInfo external{VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_IMAGE_CREATE_INFO, &modifierList};
  external.handleTypes = VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT;
  const VkImageCreateInfo info = drmImageInfo(format, extent, usage, &external);
  VkImage image;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  image_ = Unique<VkImage>(device, image);
  device.name(image, VK_OBJECT_TYPE_IMAGE, name);

  // One dedicated allocation, exported: some drivers require it for external memory, none refuse it.
  VkMemoryDedicatedRequirements dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS};
  VkMemoryRequirements2 requirements{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2, &dedicated};
  const VkImageMemoryRequirementsInfo2 requirementsInfo{VK_STRUCTURE_TYPE_IMAGE_MEMORY_REQUIREMENTS_INFO_2, nullptr,
                                                         image};
  vkGetImageMemoryRequirements2(device, &requirementsInfo, &requirements);
  VkMemoryDedicatedAllocateInfo dedicatedInfo{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO};
  dedicatedInfo.image = image;
  VkExportMemoryAllocateInfo exportInfo{VK_STRUCTURE_TYPE_EXPORT_MEMORY_ALLOCATE_INFO, &dedicatedInfo};
  exportInfo.handleTypes = VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT;
  memory_ = device.allocate(requirements.memoryRequirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &exportInfo);
  memorySize_ = requirements.memoryRequirements.size;
  VK_CHECK(vkBindImageMemory(device, image, memory_, 0));

  VkImageDrmFormatModifierPropertiesEXT chosen{VK_STRUCTURE_TYPE_IMAGE_DRM_FORMAT_MODIFIER_PROPERTIES_EXT};
  VK_CHECK(device.getImageDrmFormatModifierProperties(device, image, &chosen));
  modifier_ = chosen.drmFormatModifier;
  uint32_t planeCount = 0;
  for (const auto& entry : drmModifierList(device.physical(), format))
    if (entry.drmFormatModifier == modifier_) planeCount = entry.drmFormatModifierPlaneCount;
  if (planeCount == 0 || planeCount > kDrmMemoryPlanes.size())
    throw Error(fmt::format("the driver chose modifier {:#x} with {} memory planes", modifier_, planeCount));

  std::vector<drm::Plane> layouts;
  for (uint32_t plane = 0; plane < planeCount; ++plane) {
    const VkImageSubresource subresource{VkImageAspectFlags(kDrmMemoryPlanes[plane]), 0, 0};
    VkSubresourceLayout layout{};
    vkGetImageSubresourceLayout(device, image, &subresource, &layout);
    layouts.push_back({layout.offset, layout.size, layout.rowPitch});
  }
  const std::string problem =
      drm::checkPlanes(layouts, planeCount, modifier_, extent.width, extent.height, 4, memorySize_);
  if (!problem.empty()) throw Error(fmt::format("{}: the planes cannot be described: {}", name, problem));
  for (const drm::Plane& layout : layouts) {
    const VkMemoryGetFdInfoKHR fdInfo{VK_STRUCTURE_TYPE_MEMORY_GET_FD_INFO_KHR, nullptr, memory_,
                                      VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT};
    int fd = -1;
    VK_CHECK(device.getMemoryFd(device, &fdInfo, &fd));
    planes_.push_back({FileDescriptor(fd), layout});
  }
}

VkImageCreateInfo drmImageInfo(VkFormat format, VkExtent2D extent, VkImageUsageFlags usage, const void* next) {
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO, next};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {extent.width, extent.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_DRM_FORMAT_MODIFIER_EXT;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  return info;
}

namespace {
void recordDrmBarrier(VkCommandBuffer cmd, VkImageMemoryBarrier2 barrier, VkImage image) {
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dependency.imageMemoryBarrierCount = 1;
  dependency.pImageMemoryBarriers = &barrier;
  vkCmdPipelineBarrier2(cmd, &dependency);
}
}  // namespace

void beginExportedCopy(VkCommandBuffer cmd, VkImage image) {
  VkImageMemoryBarrier2 step{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  step.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;  // after this queue's copy into it frames ago
  step.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  step.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  step.dstAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  step.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  step.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  step.srcQueueFamilyIndex = step.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  recordDrmBarrier(cmd, step, image);
}

void endExportedCopy(VkCommandBuffer cmd, VkImage image, uint32_t queueFamily) {
  VkImageMemoryBarrier2 step{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  step.srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  step.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
  step.dstStageMask = VK_PIPELINE_STAGE_2_NONE;  // a release: the consumer's acquire orders its reads
  step.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  step.newLayout = VK_IMAGE_LAYOUT_GENERAL;
  step.srcQueueFamilyIndex = queueFamily;
  step.dstQueueFamilyIndex = VK_QUEUE_FAMILY_EXTERNAL;
  recordDrmBarrier(cmd, step, image);
}

void acquireImported(VkCommandBuffer cmd, VkImage image, uint32_t queueFamily) {
  VkImageMemoryBarrier2 step{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  step.dstStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
  step.dstAccessMask = VK_ACCESS_2_TRANSFER_READ_BIT;
  step.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
  step.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  step.srcQueueFamilyIndex = VK_QUEUE_FAMILY_EXTERNAL;
  step.dstQueueFamilyIndex = queueFamily;
  recordDrmBarrier(cmd, step, image);
}

}  // namespace vitrine::gpu
