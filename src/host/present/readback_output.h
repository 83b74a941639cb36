#pragma once
// An output whose frames go to another program (a PipeWire node, a stream's encoder) rather than to a
// screen: the frame is drawn, through this output's own warp and after the flash guard like a window's,
// into an image of its own, then copied into the next of a few host-visible buffers. Nothing waits for
// that copy: each frame, the newest copy that has finished is handed to the output's FrameSink on the
// frame thread, and a frame that finds every buffer still in flight is not drawn at all, only counted.
#include "gpu/readback_ring.h"
#include "host/present/output.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>

namespace vitrine::host {

// One frame read back: RGBA, 8 bits a channel, display-encoded (sRGB) as a window shows it, top row first.
struct PublishedFrame {
  std::span<const std::byte> bytes;  // valid during FrameSink::frame only
  uint32_t width = 0, height = 0;
  uint32_t stride = 0;  // bytes from one row to the next
  uint64_t index = 0;   // the frame's number (the simulation step it shows)
  double time = 0.0;    // the scene's time it shows, in seconds
};

// A sink that takes frames as images on the GPU (exported DMA-BUFs a consumer reads in place) rather
// than as bytes read back. Called on the frame thread; nothing here waits for the GPU or the consumer.
class ImageHandOver {
 public:
  struct Target {
    VkImage image = VK_NULL_HANDLE;
    VkExtent2D extent{};
    VkFormat format = VK_FORMAT_UNDEFINED;  // the same byte order as the output's image: copied, else blitted
    uint64_t id = 0;
  };
  virtual ~ImageHandOver() = default;
  // Frames go this way now; false: they are read back as bytes and handed to FrameSink::frame.
  virtual bool active() const = 0;
  // A free image of `extent` for this frame's copy, kept for it until the next take() unless
  // submitted() says it was copied into; none: the frame is dropped.
  virtual std::optional<Target> take(VkExtent2D extent) = 0;
  // The copy into `id` rides on submission `serial` and shows frame `index` at scene time `time`.
  virtual void submitted(uint64_t id, uint64_t serial, uint64_t index, double time) = 0;
  // The copies the GPU has finished (up to serial `completed`) go to the consumer; images the consumer
  // side no longer uses are retired through `device`, behind the frames that may still copy into them.
  virtual void finished(uint64_t completed, const gpu::Device& device) = 0;
};

// Where a ReadbackOutput's frames go. Called on the frame thread: it copies what it keeps and returns
// at once, never waiting for a consumer, a network or a daemon.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  virtual void frame(const PublishedFrame& frame) = 0;
  // The size the other side asks for now (a consumer that negotiated another); none: keep the output's.
  virtual std::optional<VkExtent2D> wantedExtent() const { return std::nullopt; }
  // False while nobody takes the frames (no consumer yet): the output then draws and copies nothing.
  virtual bool taking() const { return true; }
  // The images it takes frames in, when it can take them so (a PipeWire consumer of DMA-BUFs).
  virtual std::shared_ptr<ImageHandOver> images() { return nullptr; }
  // How it fares: its kind and line, whether someone takes the frames, the frames it handed over and
  // those it dropped itself (the output adds the ones it dropped before they reached the sink).
  virtual Output::Health health() const = 0;
};

class ReadbackOutput final : public Output {
 public:
  static constexpr uint32_t kBuffers = 3;  // one more than the frames in flight: a copy is rarely waited out

  ReadbackOutput(const gpu::Device& device, std::string name, const maths::OutputWarp& warp, VkExtent2D extent,
                 std::unique_ptr<FrameSink> sink);
  ~ReadbackOutput() override;

  VkExtent2D extent() const override { return image_.extent2d(); }
  // Hands the newest finished copy to the sink, follows a size the sink asks for, and is false while
  // the sink takes nothing, or (the frame dropped and counted) while every buffer is still in flight.
  bool acquire(uint32_t slot, bool vsync) override;
  BlitDestination destination(VkPipelineStageFlags2 acquireStage) const override;
  std::pair<VkSemaphore, VkSemaphore> semaphores(uint32_t) const override { return {}; }
  void drawn(VkCommandBuffer cmd, gpu::PassTimer* timer, const FrameInput& shown) override;
  void present() override;  // the copies recorded this frame ride on the submission just made
  Health health() const override;

  FrameSink& sink() { return *sink_; }
  // The format of the image each frame is drawn into, 8-bit RGBA with the display's encoding: UNORM
  // written by the compute present where the device stores without a declared format, else sRGB.
  static VkFormat frameFormat(const gpu::Device& device);
  uint64_t dropped() const { return dropped_; }  // frames this output dropped before the sink saw them

 private:
  struct Copies;  // the buffers of one size, retired together when the size changes
  void build(VkExtent2D extent);
  void collect();  // the newest finished copy to the sink
  void copyToTarget(VkCommandBuffer cmd);  // this frame into the image the sink's hand-over gave

  const gpu::Device& device_;
  std::unique_ptr<FrameSink> sink_;
  std::shared_ptr<ImageHandOver> images_;       // the sink's, when it takes images
  std::optional<ImageHandOver::Target> target_;  // this frame's image there
  gpu::Image image_;
  std::unique_ptr<Copies> copies_;
  struct Stamp {
    uint64_t index = 0;
    double time = 0.0;
  };
  Stamp targetStamp_{};                       // the frame copied into target_
  bool targetCopied_ = false;
  std::array<Stamp, 2 * kBuffers> stamps_{};  // the frames of the copies in flight, by their tag
  uint64_t copied_ = 0;                       // copies recorded: the next tag
  uint64_t dropped_ = 0;
  std::optional<VkExtent2D> refused_;  // a size the sink asked that the device could not hold
};

}  // namespace vitrine::host
