#pragma once
// An output of the gallery besides its main window: somewhere the frame the scene rendered once is shown
// again, through the output's own warp (its region, turn, pin and soft edges). A window on a monitor or
// a projector is one kind (host/present/output_window.h); another kind (a video node, a stream) implements the
// same few calls, and the gallery's outputs (host/gallery/gallery_outputs.h) draw it and pin it with projector
// setup like any other.
#include "gpu/pass_timer.h"
#include "host/scene_renderer.h"
#include "maths/output_warp.h"

#include <cstdint>
#include <string>
#include <utility>

namespace vitrine::host {

class Output {
 public:
  virtual ~Output() = default;
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  // What the settings file keeps this output's warp under (projector setup's pin).
  const std::string& name() const { return name_; }
  maths::OutputWarp& warp() { return warp_; }
  const maths::OutputWarp& warp() const { return warp_; }
  virtual VkExtent2D extent() const = 0;  // its size in pixels now

  // Frame slot `slot`'s image: false when the output takes no frame now (hidden, being rebuilt), and
  // then nothing is drawn to it this frame.
  virtual bool acquire(uint32_t slot, bool vsync) = 0;
  // The acquired image as the present pass's destination, first used at `acquireStage`.
  virtual BlitDestination destination(VkPipelineStageFlags2 acquireStage) const = 0;
  // What the frame's submission waits for before drawing to the image, and signals once it is drawn;
  // none (null handles) for an image of the output's own that no presentation engine shares.
  virtual std::pair<VkSemaphore, VkSemaphore> semaphores(uint32_t slot) const = 0;
  // After the present pass has drawn the frame `shown` to the image, in the same command buffer: an
  // output that takes its frames back to the CPU records its copy here, timed by `timer`.
  virtual void drawn(VkCommandBuffer /*cmd*/, gpu::PassTimer* /*timer*/, const FrameInput& /*shown*/) {}
  virtual void present() = 0;  // after the submission: shows what was drawn

  // How the output fares, for the menu, the remote page and the console: a window is always fine; a
  // published node or a stream says who takes its frames and how many it had to drop.
  struct Health {
    std::string kind = "window";  // "window", "pipewire", "stream"
    std::string line;             // one line: "OBS reading 1920x1080 RGBx", "reconnecting in 2 s (refused)"
    uint64_t frames = 0;          // frames handed over
    uint64_t dropped = 0;         // frames it could not take, dropped rather than waited for
    bool connected = true;        // someone takes the frames now
  };
  virtual Health health() const { return {}; }

 protected:
  Output(std::string name, const maths::OutputWarp& warp) : name_(std::move(name)), warp_(warp) {}

 private:
  std::string name_;
  maths::OutputWarp warp_;
};

}  // namespace vitrine::host
