#pragma once
// A film's frames on their way from the GPU to the encoder, without the frame loop waiting for them:
// each rendered frame is packed on the GPU into the bytes the encoder takes (shaders/host/film_pack.comp:
// 8-bit sRGB, or 16-bit for a 10-bit film, exactly as the CPU made them from the read-back frame) and
// copied into the next of a few host-readable slots. The encoder's thread waits for that copy, encodes
// the bytes and hands the slot back; the frame loop waits only when every slot is still in use.
#include "film/film_format.h"
#include "gpu/program.h"
#include "gpu/resources.h"

#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <span>
#include <vector>

namespace vitrine::host {

class FilmFrames {
 public:
  FilmFrames(const gpu::Device& device, VkExtent2D size, film::DisplayLayout layout, uint32_t slots);
  ~FilmFrames();  // waits for the GPU: a slot's copy may still be running
  FilmFrames(const FilmFrames&) = delete;
  FilmFrames& operator=(const FilmFrames&) = delete;

  // Packs `frame` (a rendered frame's output, whose rendering was submitted before) into the next slot
  // and submits it; returns the slot. Waits while that slot's bytes are still being encoded.
  uint32_t pack(gpu::Image& frame);
  // The slot's bytes, once its copy has finished (waited for here): from any thread.
  std::span<const std::byte> bytes(uint32_t slot);
  // The slot's bytes are no longer read: the frame loop may pack into it again.
  void release(uint32_t slot);
  // Seconds the frame loop waited for a slot, and the encoder for a copy.
  double slotWaits() const { return slotWaits_; }
  double copyWaits() const { return copyWaits_; }

 private:
  struct Slot {
    gpu::Buffer bytes;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    uint64_t serial = 0;
    bool busy = false;
  };
  const gpu::Device& device_;
  VkExtent2D size_;
  film::DisplayLayout layout_;
  uint32_t groups_;   // invocations of the packing pass
  size_t byteCount_;  // the packed frame, whole words
  gpu::ProgramLibrary programs_;
  gpu::ComputeProgram program_;
  gpu::Buffer table_;   // half-float bits to display values
  gpu::Buffer packed_;  // what the pass writes, on the device
  gpu::Unique<VkCommandPool> pool_;
  std::vector<Slot> slots_;
  size_t next_ = 0;
  std::mutex mutex_;
  std::condition_variable freed_;
  double slotWaits_ = 0.0, copyWaits_ = 0.0;
};

}  // namespace vitrine::host
