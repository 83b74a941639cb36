#include "gpu/readback_ring.h"

#include <fmt/format.h>

#include <algorithm>

namespace vitrine::gpu {

ReadbackRing::ReadbackRing(const Device& device, FrameResources& resources, VkDeviceSize bytes, uint32_t slots,
                           const std::string& name)
    : device_(device), resources_(resources), bytes_(bytes) {
  // A declaration a slot rather than one PerFrame buffer: a slot is taken again once its copy has
  // finished, which follows the submissions, not the frames in flight (more slots than frames).
  for (uint32_t i = 0; i < slots; ++i)
    slots_.push_back({resources.declare(BufferDecl{.name = fmt::format("{} {}", name, i),
                                                   .size = BufferSize::absolute(bytes),
                                                   .usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                   .memory = MemoryUse::Readback}),
                      0, 0.0, false});
}

bool ReadbackRing::full() const {
  const Slot& slot = slots_[next_];
  return slot.pending && slot.serial > device_.completed();
}

ReadbackRing::Slot* ReadbackRing::take() {
  if (full()) return nullptr;  // all in flight: skip, never wait
  Slot& slot = slots_[next_];
  next_ = (next_ + 1) % slots_.size();
  slot.serial = device_.lastSubmitted() + 1;
  slot.stamped = false;
  slot.pending = true;
  return &slot;
}

bool ReadbackRing::record(VkCommandBuffer cmd, Buffer& source, double tag) {
  Slot* slot = take();
  if (!slot) return false;
  Buffer& destination = resources_.current(slot->buffer);
  source.use(cmd, use::TransferSrcBuffer);
  destination.use(cmd, use::TransferDstBuffer);
  const VkBufferCopy region{0, 0, bytes_};
  vkCmdCopyBuffer(cmd, source.handle(), destination.handle(), 1, &region);
  destination.use(cmd, use::HostReadBuffer);
  slot->tag = tag;
  return true;
}

bool ReadbackRing::record(VkCommandBuffer cmd, Image& source, double tag) {
  Slot* slot = take();
  if (!slot) return false;
  recordReadback(cmd, source, resources_.current(slot->buffer));
  slot->tag = tag;
  return true;
}

void ReadbackRing::submitted(uint64_t serial) {
  for (Slot& slot : slots_)
    if (slot.pending && !slot.stamped) {
      slot.serial = std::max(slot.serial, serial);
      slot.stamped = true;
    }
}

std::optional<ReadbackRing::Result> ReadbackRing::poll() {
  const uint64_t completed = device_.completed();
  Slot* newest = nullptr;
  uint32_t superseded = 0;
  for (Slot& slot : slots_) {
    if (!slot.pending || slot.serial > completed) continue;
    ++superseded;
    // Tags rise with the serials; two copies on one submission keep the later-recorded tag.
    if (!newest || slot.serial > newest->serial || (slot.serial == newest->serial && slot.tag > newest->tag)) {
      if (newest) newest->pending = false;
      newest = &slot;
    } else {
      slot.pending = false;
    }
  }
  if (!newest) return std::nullopt;
  newest->pending = false;
  const Buffer& buffer = resources_.current(newest->buffer);
  buffer.invalidate();
  return Result{{static_cast<const std::byte*>(buffer.mapped()), size_t(bytes_)}, newest->tag, superseded - 1};
}

}  // namespace vitrine::gpu
