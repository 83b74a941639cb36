#pragma once
// The flash guard: a pass over the final frame, for every scene and every mode, that keeps what is
// shown within WCAG 2.3.1's general and red flash thresholds (host/flash_guard_math.h says how they
// are counted; docs/INSTALLATIONS.md what the guard does and does not promise). It stands in for the
// present pass: it measures the pixels that would make a transition against what was shown last frame,
// decides on the GPU whether the one-second window allows this frame's transitions, and shows the
// frame, holding back the pixels whose transitions it did not allow. A frame within the thresholds is
// written exactly as the present pass writes it.
//
// Its state (what was shown last, and the ages of the transitions shown lately) lives on the GPU and
// belongs to the host's output, not to a scene: the gallery keeps one across scene switches and kiosk
// cross-fades. Nothing is read back.
#include "gpu/program.h"
#include "gpu/resources.h"

#include <limits>

namespace vitrine::host {

// What the guard scales onto the output: the scene's target and, in a cross-fade, the incoming one.
struct GuardSources {
  VkImageView source = VK_NULL_HANDLE;
  VkImageView incoming = VK_NULL_HANDLE;  // `source` when there is no fade
  float fade = 0.0f;
};

class FlashGuard {
 public:
  FlashGuard(const gpu::Device& device, gpu::ProgramLibrary& programs);

  // The guarded frame of `extent` pixels, for the frame showing simulation time `time` (seconds; a time
  // before the last frame's, a new scene's, starts the guard afresh): the image every output presents,
  // which the guard keeps to measure the next frame against. Valid until the next call.
  gpu::Image& guard(VkCommandBuffer cmd, const GuardSources& sources, VkExtent2D extent, double time);
  // Forget what was shown: the next frame is shown as it is (a new scene in the gallery counts from it).
  void reset() { lastTime_ = std::numeric_limits<double>::quiet_NaN(); }

 private:
  const gpu::Device& device_;
  gpu::ComputeProgram measure_;
  gpu::ComputeProgram decide_;
  gpu::ComputeProgram show_;
  gpu::Buffer state_;  // shader::HostFlashGuardState
  gpu::Image held_;    // what was shown last frame, linear, at the frame's size
  double lastTime_ = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace vitrine::host
