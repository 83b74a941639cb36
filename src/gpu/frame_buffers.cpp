// FrameResources' buffers: the declared counterpart of its images (frame_resources.cpp).
#include "gpu/buffer_commands.h"
#include "gpu/frame_resources.h"

#include "core/error.h"

#include <fmt/format.h>

#include <utility>

namespace vitrine::gpu {

BufferHandle FrameResources::declare(BufferDecl decl) { return {declareIn(buffers_, std::move(decl))}; }

void FrameResources::redeclare(BufferHandle handle, BufferDecl decl) {
  redeclareIn(buffers_, handle.index, std::move(decl));
}

void FrameResources::create(BufferEntry& entry, VkExtent2D target) {
  const BufferDecl& decl = entry.decl;
  const VkDeviceSize bytes =
      decl.size.isRelative() ? VkDeviceSize(target.width) * target.height * decl.size.perPixel : decl.size.bytes;
  if (bytes == 0) throw Error(fmt::format("Buffer {} is declared with no size", decl.name));
  if (decl.initial.size() > bytes)
    throw Error(fmt::format("Buffer {}: {} initial bytes for {}", decl.name, decl.initial.size(), bytes));
  VkBufferUsageFlags usage = decl.usage;
  if (!decl.initial.empty() || decl.clear) usage |= VK_BUFFER_USAGE_TRANSFER_DST_BIT;  // written by copies
  if (decl.state) usage |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  const size_t count = decl.pairing == Pairing::PingPong ? 2 : decl.pairing == Pairing::PerFrame ? framesInFlight_ : 1;
  for (Buffer& old : entry.buffers) device_.retire(std::move(old));
  entry.buffers.clear();
  for (size_t i = 0; i < count; ++i)
    entry.buffers.emplace_back(device_, bytes, usage, decl.memory,
                               count == 1 ? decl.name : fmt::format("{} {}", decl.name, i));
  entry.front = 0;
  entry.fresh = true;
  entry.restored.clear();  // meant for the buffers just retired
}

void FrameResources::beginBuffers(VkCommandBuffer cmd, StreamArena& stream) {
  for (BufferEntry& entry : buffers_) {
    if (entry.buffers.empty()) continue;
    if (std::exchange(entry.fresh, false))
      for (Buffer& buffer : entry.buffers) {
        if (entry.decl.clear) fillBuffer(cmd, buffer, entry.decl.clearValue, entry.decl.initialUse);
        if (!entry.decl.initial.empty()) uploadBuffer(cmd, stream, buffer, 0, entry.decl.initial, entry.decl.initialUse);
      }
    if (!entry.restored.empty())  // a checkpoint's contents, over the initial ones
      uploadBuffer(cmd, stream, entry.buffers[entry.front], 0, std::exchange(entry.restored, {}), entry.decl.initialUse);
  }
}

// A buffer whose initial contents are still pending holds garbage (see the images' ready()).
FrameResources::BufferEntry& FrameResources::ready(BufferHandle handle) {
  BufferEntry& entry = buffers_.at(handle.index);
  if (entry.buffers.empty()) throw Error(fmt::format("{} is used before the target's size is known", entry.decl.name));
  if ((entry.fresh && (!entry.decl.initial.empty() || entry.decl.clear)) || !entry.restored.empty())
    throw Error(fmt::format("{} is used before its initial contents were written: (re)declare it in the scene's "
                            "constructor or update(), not while recording",
                            entry.decl.name));
  return entry;
}

Buffer& FrameResources::current(BufferHandle handle) {
  BufferEntry& entry = ready(handle);
  if (entry.decl.pairing == Pairing::PerFrame) return entry.buffers.at(slot_);
  return entry.buffers[entry.front];
}

Buffer& FrameResources::previous(BufferHandle handle) {
  BufferEntry& entry = ready(handle);
  if (entry.decl.pairing != Pairing::PingPong) throw Error(fmt::format("{} is not a ping-pong pair", entry.decl.name));
  return entry.buffers[entry.front ^ 1u];
}

std::vector<std::byte> FrameResources::download(BufferHandle handle) {
  Buffer& buffer = current(handle);
  const BufferDecl& decl = buffers_.at(handle.index).decl;
  if (!decl.state) throw Error(fmt::format("{} is not declared as simulation state: it cannot be saved", decl.name));
  Buffer staging(device_, buffer.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::Readback, decl.name + " checkpoint");
  device_.submitNow([&](VkCommandBuffer cmd) {
    buffer.use(cmd, use::TransferSrcBuffer);
    staging.use(cmd, use::TransferDstBuffer);
    const VkBufferCopy region{0, 0, buffer.size()};
    vkCmdCopyBuffer(cmd, buffer.handle(), staging.handle(), 1, &region);
    staging.use(cmd, use::HostReadBuffer);
  });
  staging.invalidate();
  const auto view = staging.view<const std::byte>();
  return {view.begin(), view.end()};
}

void FrameResources::restore(BufferHandle handle, std::vector<std::byte> contents) {
  BufferEntry& entry = buffers_.at(handle.index);
  if (!entry.decl.state || entry.buffers.empty() || contents.size() != entry.buffers[entry.front].size())
    throw Error(fmt::format("{}: {} bytes of saved state do not fill it", entry.decl.name, contents.size()));
  entry.restored = std::move(contents);
}

void FrameResources::flip(BufferHandle handle) { buffers_.at(handle.index).front ^= 1u; }

}  // namespace vitrine::gpu
