#pragma once
// Small results the GPU computes every frame and the CPU wants back (statistics, a phase level),
// read a few frames later without ever stalling: each frame's copy goes into the next of a few
// host-readable buffers, and poll() hands over the newest one whose submission has finished. When
// every buffer is still in flight, that frame's copy is skipped rather than waited for. The buffers
// are declared in the scene's FrameResources, so the host owns and retires them with its others.
#include "gpu/frame_resources.h"

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::gpu {

class ReadbackRing {
 public:
  ReadbackRing(const Device& device, FrameResources& resources, VkDeviceSize bytes, uint32_t slots,
               const std::string& name);

  // Records a copy of `source` (its first `bytes`) into a free slot, tagged (a frame index or a
  // time); false when no slot is free this frame.
  bool record(VkCommandBuffer cmd, Buffer& source, double tag);
  // The same for an image's level 0, its texels row after row (`bytes` is the whole level's size).
  bool record(VkCommandBuffer cmd, Image& source, double tag);
  // The copies recorded since are carried by submission `serial` or an earlier one. A copy is taken to
  // ride on the next submission otherwise, which another submission recorded in between (a swapchain's
  // acquire on a software device) would make too early.
  void submitted(uint64_t serial);
  bool full() const;  // no slot free: the next record() would skip

  struct Result {
    std::span<const std::byte> bytes;  // valid until the next record() into that slot
    double tag;
    uint32_t superseded = 0;  // older finished copies dropped in its favour
  };
  // The newest finished copy not yet handed over; older finished ones are dropped with it.
  std::optional<Result> poll();

 private:
  struct Slot {
    BufferHandle buffer;
    uint64_t serial = 0;  // of the submission that fills it
    double tag = 0.0;
    bool pending = false;
    bool stamped = false;  // serial set by submitted()
  };
  Slot* take();  // the next slot, when free
  const Device& device_;
  FrameResources& resources_;
  VkDeviceSize bytes_;
  std::vector<Slot> slots_;
  size_t next_ = 0;
};

}  // namespace vitrine::gpu
