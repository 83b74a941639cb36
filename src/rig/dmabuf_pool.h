#pragma once
// The DMA-BUF images a PipeWire node hands its consumer, shared by two threads. PipeWire's thread adds
// an image for each buffer the stream allocates, marks a buffer free when the consumer gives it back,
// and queues the newest finished frame; the frame thread takes a free image for a frame's copy, says
// which submission carries it, and finds out, without waiting, which copies the GPU has finished.
//
// A buffer moves: with the consumer -> free -> taken (this frame copies into it) -> copying (its
// submission not finished) -> done (finished, waiting for PipeWire's thread) -> with the consumer.
// The consumer never gets a buffer the GPU is still writing, and no buffer it holds is written: without
// explicit sync metadata (PipeWire 0.3.65 has none), finishing first is the only sync a consumer sees.
#include "host/present/readback_output.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace vitrine::gpu {
class ExportedImage;
}

namespace vitrine::rig {

class DmaBufPool final : public host::ImageHandOver {
 public:
  // `wake` is called on the frame thread when a copy has finished (PipeWire's thread then queues it).
  explicit DmaBufPool(std::function<void()> wake);
  ~DmaBufPool() override;

  // PipeWire's thread. `key` names the stream's buffer. An image starts with the consumer (the stream
  // has it until it is dequeued).
  void add(const void* key, std::unique_ptr<gpu::ExportedImage> image, VkExtent2D extent, VkFormat format);
  void remove(const void* key);  // the image is retired by the frame thread, behind its last copy
  void given(const void* key);   // dequeued: free for a copy
  struct Done {
    const void* key;
    uint64_t index;
    double time;
  };
  // The newest finished copy, now with the consumer; older finished ones are free again and counted in
  // `superseded`.
  std::optional<Done> takeDone(uint64_t& superseded);
  void setActive(bool active);
  size_t size() const;

  // The frame thread (host::ImageHandOver).
  bool active() const override;
  std::optional<Target> take(VkExtent2D extent) override;
  void submitted(uint64_t id, uint64_t serial, uint64_t index, double time) override;
  void finished(uint64_t completed, const gpu::Device& device) override;
  // The copies up to serial `completed` are done (wakes PipeWire's thread if any); true if any.
  bool markFinished(uint64_t completed);

 private:
  enum class State { Consumer, Free, Taken, Copying, Done };
  struct Slot {
    const void* key;
    uint64_t id;  // never reused: a frame's id outlives a slot that was removed
    std::unique_ptr<gpu::ExportedImage> image;
    VkImage handle;
    VkExtent2D extent;
    VkFormat format;
    State state = State::Consumer;
    uint64_t serial = 0;
    uint64_t index = 0;
    double time = 0.0;
  };
  Slot* find(const void* key);

  const std::function<void()> wake_;
  mutable std::mutex lock_;
  std::vector<Slot> slots_;
  std::vector<std::unique_ptr<gpu::ExportedImage>> removed_;  // for the frame thread to retire
  uint64_t nextId_ = 1;
  bool active_ = false;
};

}  // namespace vitrine::rig
