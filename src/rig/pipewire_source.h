#pragma once
// A PipeWire video source: the frames of a published output (host/present/readback_output.h) offered as
// a named node (media.class Video/Source) that other programs take: OBS, a GStreamer pipewiresrc, a
// browser through the portal. The consumer negotiates the format (BGRx, RGBx, BGRA or RGBA), the size
// (the output's by default; the output follows another) and the rate. Frames go as DMA-BUFs where the
// device exports them and the consumer takes one of the device's DRM format modifiers (the GPU copies
// each frame into an exported image; it is queued once the copy has finished), else through shared
// memory (read back, then copied by PipeWire's thread).
//
// Threads: PipeWire's run on a thread loop of their own. With shared memory, the frame thread copies
// the newest frame into a mailbox and signals the loop; the loop's process callback copies it into a
// buffer it dequeued. With DMA-BUFs, the frame thread copies on the GPU into a buffer the consumer gave
// back (rig/dmabuf_pool.h) and signals the loop once that copy has finished; the loop queues it. A
// frame the consumer had no buffer for, or one a newer frame replaced before the loop took it, is
// dropped and counted: nothing on the frame thread waits for PipeWire, a consumer, the daemon or the GPU.
// Without a daemon the source says so once on the console and tries again every few seconds.
#include "gpu/drm_modifiers.h"
#include "host/present/readback_output.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vitrine::rig {

// What a node can offer as DMA-BUFs: the device that exports them, and for each byte order of the frame
// (R,G,B,A and B,G,R,A) the Vulkan format and the DRM format modifiers the copy can write.
struct DmaBufOffer {
  const gpu::Device* device = nullptr;  // none: shared memory only
  VkFormat rgba = VK_FORMAT_UNDEFINED, bgra = VK_FORMAT_UNDEFINED;
  std::vector<gpu::drm::DriverModifier> rgbaModifiers, bgraModifiers;
  std::string why;  // why there is none, when there is none
};

class PipeWireSource final : public host::FrameSink {
 public:
  static constexpr std::chrono::seconds kRetry{5};  // between tries to reach a daemon that is not there

  // What `device` can offer, the frame's format being ReadbackOutput::frameFormat's.
  static DmaBufOffer dmaBufOffer(const gpu::Device& device);

  // `node`: the node's name (node.name); `extent`: the size it offers first; `fps`: the rate it offers.
  PipeWireSource(std::string node, VkExtent2D extent, uint32_t fps, DmaBufOffer offer = {});
  ~PipeWireSource() override;

  void frame(const host::PublishedFrame& frame) override;
  std::optional<VkExtent2D> wantedExtent() const override;
  bool taking() const override;
  host::Output::Health health() const override;
  std::shared_ptr<host::ImageHandOver> images() override;

  struct Impl;  // PipeWire's objects and callbacks: only this file's source includes PipeWire

 private:
  std::unique_ptr<Impl> impl_;
};

// The gallery's output that publishes its frames as the PipeWire node `node`, shown through `warp` at
// `extent` until a consumer asks another size; `name` is what the settings keep its warp under.
std::unique_ptr<host::Output> makePipeWireOutput(const gpu::Device& device, std::string name, std::string node,
                                                 const maths::OutputWarp& warp, VkExtent2D extent);

}  // namespace vitrine::rig
