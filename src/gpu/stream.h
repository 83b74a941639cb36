#pragma once
// Memory the CPU writes for the GPU to read in the frame being recorded: staging data for uploads
// into buffers and images, and per-frame uniform or parameter blocks. Allocation is a pointer bump in
// host-visible chunks; a chunk is reused once every submission that read it has finished, so nothing
// is allocated per frame once the arena has grown to the working set.
#include "gpu/resources.h"

#include <cstddef>
#include <cstring>
#include <span>
#include <vector>

namespace vitrine::gpu {

struct StreamSlice {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  VkDeviceSize size = 0;
  std::byte* mapped = nullptr;
};

class StreamArena {
 public:
  explicit StreamArena(const Device& device, VkDeviceSize chunkBytes = VkDeviceSize(4) << 20);

  // `bytes` of memory valid for the submission being recorded (and no longer).
  StreamSlice allocate(VkDeviceSize bytes, VkDeviceSize alignment = 256);
  StreamSlice write(std::span<const std::byte> data, VkDeviceSize alignment = 256) {
    StreamSlice slice = allocate(data.size(), alignment);
    std::memcpy(slice.mapped, data.data(), data.size());
    return slice;
  }
  template <typename T> StreamSlice writeValue(const T& value) { return write(std::as_bytes(std::span(&value, 1))); }
  size_t chunkCount() const { return chunks_.size(); }

 private:
  struct Chunk {
    Buffer buffer;
    VkDeviceSize used = 0;
    uint64_t lastSerial = 0;  // the newest submission that reads from it
  };
  const Device& device_;
  VkDeviceSize chunkBytes_;
  std::vector<Chunk> chunks_;
  size_t current_ = 0;
};

// Copies CPU data into a buffer / level 0 of an image through the arena; the destination ends in
// `after` (for an image with mips, every level is generated and ends there).
void uploadBuffer(VkCommandBuffer cmd, StreamArena& arena, Buffer& dst, VkDeviceSize offset,
                  std::span<const std::byte> data, const BufferUse& after);
void uploadImage(VkCommandBuffer cmd, StreamArena& arena, Image& dst, std::span<const std::byte> level0,
                 const ImageUse& after);

}  // namespace vitrine::gpu
