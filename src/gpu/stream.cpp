#include "gpu/stream.h"

#include <fmt/format.h>

#include "core/error.h"

#include <algorithm>

namespace vitrine::gpu {

StreamArena::StreamArena(const Device& device, VkDeviceSize chunkBytes) : device_(device), chunkBytes_(chunkBytes) {}

StreamSlice StreamArena::allocate(VkDeviceSize bytes, VkDeviceSize alignment) {
  const uint64_t serial = device_.lastSubmitted() + 1;  // the submission being recorded
  auto fits = [&](Chunk& chunk) {
    const VkDeviceSize start = (chunk.used + alignment - 1) / alignment * alignment;
    return start + bytes <= chunk.buffer.size();
  };
  if (chunks_.empty() || !fits(chunks_[current_])) {
    // Reuse a chunk every reader of which has finished, else add one.
    const uint64_t completed = device_.completed();
    size_t found = chunks_.size();
    for (size_t i = 0; i < chunks_.size() && found == chunks_.size(); ++i)
      if (chunks_[i].lastSerial <= completed && chunks_[i].buffer.size() >= bytes) found = i;
    if (found == chunks_.size()) {
      constexpr VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
      // The first time, two: an arena written every frame fills its chunk sooner or later while the
      // frame that filled it is in flight, and then needs a second. Made at once, the working set is
      // there from the first frame rather than appearing minutes in (the soak saw the calibration card,
      // which writes ~2 kB a frame, grow by a chunk after 2,300 frames).
      for (size_t made = 0, wanted = chunks_.empty() ? 2 : 1; made < wanted; ++made)
        chunks_.push_back({Buffer(device_, std::max(bytes, chunkBytes_), usage, MemoryUse::Upload,
                                  fmt::format("stream chunk {}", chunks_.size())),
                           0, 0});
    }
    current_ = found;
    chunks_[current_].used = 0;
  }
  Chunk& chunk = chunks_[current_];
  const VkDeviceSize start = (chunk.used + alignment - 1) / alignment * alignment;
  chunk.used = start + bytes;
  chunk.lastSerial = serial;
  return {chunk.buffer.handle(), start, bytes, static_cast<std::byte*>(chunk.buffer.mapped()) + start};
}

void uploadBuffer(VkCommandBuffer cmd, StreamArena& arena, Buffer& dst, VkDeviceSize offset,
                  std::span<const std::byte> data, const BufferUse& after) {
  if (offset + data.size() > dst.size()) throw Error("upload larger than its destination buffer");
  const StreamSlice staging = arena.write(data, 16);
  dst.use(cmd, use::TransferDstBuffer);
  const VkBufferCopy region{staging.offset, offset, data.size()};
  vkCmdCopyBuffer(cmd, staging.buffer, dst.handle(), 1, &region);
  dst.use(cmd, after);
}

void uploadImage(VkCommandBuffer cmd, StreamArena& arena, Image& dst, std::span<const std::byte> level0,
                 const ImageUse& after) {
  const StreamSlice staging = arena.write(level0, 16);
  dst.discard();  // every texel of level 0 is replaced
  dst.use(cmd, use::TransferDst);
  VkBufferImageCopy region{};
  region.bufferOffset = staging.offset;
  region.imageSubresource = {dst.desc().aspect, 0, 0, 1};
  region.imageExtent = dst.extent();
  vkCmdCopyBufferToImage(cmd, staging.buffer, dst.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  if (dst.desc().mips > 1)
    generateMips(cmd, dst, after);
  else
    dst.use(cmd, after);
}

}  // namespace vitrine::gpu
