#pragma once
// Buffers and images, one dedicated allocation each. Vitrine's resources are few and large, so a
// general-purpose sub-allocator would add code without saving anything measurable.
//
// Each buffer and image remembers how it was last used. `use(cmd, next)` records the barrier from
// that use to `next` (none between two reads) and remembers `next`: barriers are derived, not written.
#include "gpu/barriers.h"
#include "gpu/device.h"

#include <span>
#include <string>
#include <vector>

namespace vitrine::gpu {

enum class MemoryUse {
  Device,    // GPU-only
  Upload,    // host-visible, written by the CPU each frame (mapped for the buffer's lifetime)
  Readback,  // host-visible and cached, read by the CPU after the submission finished
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

  void use(VkCommandBuffer cmd, const BufferUse& next);
  const BufferUse& lastUse() const { return last_; }

 private:
  const Device* device_ = nullptr;
  Unique<VkBuffer> buffer_;
  Unique<VkDeviceMemory> memory_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  BufferUse last_ = use::BufferNone;
};

struct ImageDesc {
  VkExtent3D extent{1, 1, 1};
  VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkImageUsageFlags usage = 0;
  VkImageType type = VK_IMAGE_TYPE_2D;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
  uint32_t mips = 1;  // 0: the full chain down to 1x1
  VkFormat storageFormat = VK_FORMAT_UNDEFINED;  // set: storageView() writes the bits in this format
};

uint32_t fullMipCount(VkExtent3D extent);

class Image {
 public:
  Image() = default;
  Image(const Device& device, const ImageDesc& desc, const std::string& name);

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }  // every mip level
  VkImageView mipView(uint32_t level) const;  // one level, for storage writes into a chain
  VkImageView storageView() const { return storageView_ ? VkImageView(storageView_) : view(); }
  const ImageDesc& desc() const { return desc_; }  // desc().mips is the actual count
  VkExtent2D extent2d() const { return {desc_.extent.width, desc_.extent.height}; }
  VkExtent3D extent() const { return desc_.extent; }
  VkFormat format() const { return desc_.format; }
  const std::string& name() const { return name_; }
  explicit operator bool() const { return static_cast<bool>(image_); }

  // The barrier from the last use to `next` (skipped between reads in one layout), then remembers `next`.
  void use(VkCommandBuffer cmd, const ImageUse& next);
  // The contents are not needed any more: the next use transitions from UNDEFINED.
  void discard() { last_.layout = VK_IMAGE_LAYOUT_UNDEFINED; }  // stages and accesses still order the next write
  const ImageUse& lastUse() const { return last_; }
  // For passes that change layouts level by level (mip generation): what all levels are in now.
  void assumeUse(const ImageUse& use) { last_ = use; }

 private:
  ImageDesc desc_;
  std::string name_;
  Unique<VkImage> image_;
  Unique<VkDeviceMemory> memory_;
  Unique<VkImageView> view_;
  std::vector<Unique<VkImageView>> mipViews_;
  Unique<VkImageView> storageView_;  // desc().storageFormat's view of level 0
  ImageUse last_ = use::Discard;
};

// Records a copy of an image's level 0 (2D or 3D) into a host-readable buffer, with the barriers that make it
// visible to the CPU once the submission has finished.
void recordReadback(VkCommandBuffer cmd, Image& image, Buffer& buffer);

// Fills levels 1.. of an image from level 0 by successive linear blits; leaves every level in `after`.
void generateMips(VkCommandBuffer cmd, Image& image, const ImageUse& after);

// Checks a requested 2D size against the device's limit, with a message naming both.
void checkImageSize(const Device& device, VkExtent2D extent);

}  // namespace vitrine::gpu
