#pragma once
// Images whose memory another process (a PipeWire consumer, a compositor) takes as DMA-BUFs: made with
// an explicit DRM format modifier from a list the consumer accepts, their memory exported as one file
// descriptor per memory plane, with each plane's offset and row pitch. Needs a device that enabled the
// DMA-BUF extensions (Device::exportsDmaBuf); lavapipe does not offer them.
#include "gpu/device.h"
#include "gpu/drm_modifiers.h"

#include <cstdint>
#include <utility>
#include <span>
#include <string>
#include <vector>

namespace vitrine::gpu {

// A file descriptor, closed with its owner.
class FileDescriptor {
 public:
  FileDescriptor() = default;
  explicit FileDescriptor(int fd) : fd_(fd) {}
  FileDescriptor(FileDescriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
  FileDescriptor& operator=(FileDescriptor&& other) noexcept;
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  ~FileDescriptor() { reset(); }
  void reset();
  int release() { return std::exchange(fd_, -1); }  // the caller owns it now
  int get() const { return fd_; }
  explicit operator bool() const { return fd_ >= 0; }

 private:
  int fd_ = -1;
};

// The modifiers the device can make exportable images of `format` with, for `usage`, each with its
// memory plane count; only those whose tiling features include `features` (the copy's: transfer
// destination, blit destination). Empty on a device without the DMA-BUF extensions.
std::vector<drm::DriverModifier> exportableModifiers(const Device& device, VkFormat format,
                                                             VkImageUsageFlags usage, VkFormatFeatureFlags features);

class ExportedImage {
 public:
  struct Plane {
    FileDescriptor fd;
    drm::Plane layout;
  };

  // An image of `format` and `extent` laid out with one of `modifiers` (the driver picks), in memory
  // exported as DMA-BUFs. Throws a vitrine::Error saying why when the device cannot make or export it.
  ExportedImage(const Device& device, VkFormat format, VkExtent2D extent, VkImageUsageFlags usage,
                std::span<const uint64_t> modifiers, const std::string& name);

  VkImage handle() const { return image_; }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint64_t modifier() const { return modifier_; }
  VkDeviceSize memorySize() const { return memorySize_; }
  std::span<const Plane> planes() const { return planes_; }

 private:
  Unique<VkImage> image_;
  Unique<VkDeviceMemory> memory_;
  VkFormat format_;
  VkExtent2D extent_;
  uint64_t modifier_ = 0;
  VkDeviceSize memorySize_ = 0;
  std::vector<Plane> planes_;
};

// An optimally tiled 2D image's description whose layout a DRM format modifier gives (`next` chains the
// modifier list, or an explicit modifier and plane layouts for an imported image).
VkImageCreateInfo drmImageInfo(VkFormat format, VkExtent2D extent, VkImageUsageFlags usage, const void* next);

// The barriers around a copy into an exported image: from nothing kept (the consumer gave it back, so
// its old contents are not needed) to a transfer's destination, and after the copy, to GENERAL and
// released to the external side, where the consumer reads it.
void beginExportedCopy(VkCommandBuffer cmd, VkImage image);
void endExportedCopy(VkCommandBuffer cmd, VkImage image, uint32_t queueFamily);
// The other side, for a consumer on this device: an image imported over the same memory, acquired from
// the external side in GENERAL to be a transfer's source.
void acquireImported(VkCommandBuffer cmd, VkImage image, uint32_t queueFamily);

}  // namespace vitrine::gpu
