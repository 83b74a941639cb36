#pragma once
// Buffers and images, one dedicated allocation each. Vitrine's resources are few and large, so a
// general-purpose sub-allocator would add code without saving anything measurable.
#include "gpu/device.h"

#include <span>
#include <string>

namespace vitrine::gpu {

enum class MemoryUse {
  Device,    // GPU-only
  Upload,    // host-visible, written by the CPU each frame (mapped for the buffer's lifetime)
  Readback,  // host-visible and cached, read by the CPU after a fence
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use, const std::string& name);

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  // null for MemoryUse::Device
  template <typename T> std::span<T> view() const {
    return {static_cast<T*>(mapped_), static_cast<size_t>(size_ / sizeof(T))};
  }
  // Makes device writes visible to the CPU on non-coherent memory; a no-op where coherent.
  void invalidate() const;
  explicit operator bool() const { return static_cast<bool>(buffer_); }

 private:
  const Device* device_ = nullptr;
  Unique<VkBuffer> buffer_;
  Unique<VkDeviceMemory> memory_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

struct ImageDesc {
  VkExtent3D extent{1, 1, 1};
  VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkImageUsageFlags usage = 0;
  VkImageType type = VK_IMAGE_TYPE_2D;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

class Image {
 public:
  Image() = default;
  Image(const Device& device, const ImageDesc& desc, const std::string& name);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  const ImageDesc& desc() const { return desc_; }
  VkExtent2D extent2d() const { return {desc_.extent.width, desc_.extent.height}; }
  explicit operator bool() const { return static_cast<bool>(image_); }

 private:
  ImageDesc desc_;
  Unique<VkImage> image_;
  Unique<VkDeviceMemory> memory_;
  Unique<VkImageView> view_;
};

// Records a copy of a 2D colour image in TRANSFER_SRC layout into a host-readable buffer, and the
// barrier that makes it visible to the CPU once the submission's fence has signalled.
void recordReadback(VkCommandBuffer cmd, const Image& image, const Buffer& buffer);

// Checks a requested 2D size against the device's limit, with a message naming both.
void checkImageSize(const Device& device, VkExtent2D extent);

}  // namespace vitrine::gpu
