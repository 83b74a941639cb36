#pragma once
// The part of a frame that is the same in the gallery, headless and bench modes: keep the HDR target
// and the scene's declared images at the scene's render scale, let the scene record its passes, then
// scale the target onto the caller's image (a swapchain image, or the offscreen output) in a compute
// pass when the image allows storage writes, else with a blit. Nothing here waits for the device:
// replaced targets and whole scenes are retired until the frames that used them have finished.
#include "gpu/barriers.h"
#include "gpu/frame_resources.h"
#include "gpu/resources.h"
#include "gpu/stream.h"
#include "maths/output_warp.h"
#include "host/filters/filter_chain.h"
#include "host/filters/isf_transition.h"
#include "host/flash_guard.h"
#include "scenes/scene.h"

#include <array>
#include <memory>
#include <string>
#include <string_view>

namespace vitrine::host {

struct BlitDestination {
  VkImage image;
  VkExtent2D extent;
  gpu::ImageUse before;                  // how the image was last used
  gpu::ImageUse after;                   // how the caller uses it next
  VkImageView storageView = VK_NULL_HANDLE;  // set when the image has STORAGE usage: compute path
  bool encodeSrgb = false;               // a UNORM image shown as sRGB (compute path only)
  // How this output shows the frame (a projector's turn, mirror, region, corner pin and soft edges; the
  // compute path only). Null, or the identity: the whole frame, square-on.
  const maths::OutputWarp* warp = nullptr;
  // What the GPU timings call the compute present pass onto this image (a published output's own name,
  // so a benchmark tells it from the window's).
  const char* pass = "present";
};

// The frame a scene renders for an output of `output` pixels showing it through `warp`: a quarter turn
// swaps its sides, and an output that shows a region of the frame shows it at its own size.
VkExtent2D frameExtent(VkExtent2D output, const maths::OutputWarp* warp);
// Throws vitrine::Error, starting with `where` (the warp's file), when the frame `warp` asks of an output
// of `output` pixels is larger than the device draws: a region of a few thousandths of the frame.
void checkWarpedFrame(const gpu::Device& device, VkExtent2D output, const maths::OutputWarp& warp, std::string_view where);

// Another renderer's target mixed into the output (kiosk mode's cross-fade): `weight` of it over the
// output, 0..1. The compute path only; a blit cuts instead. With a `transition`, that ISF file draws
// the two frames together at progress `weight` instead of the mix, over this renderer's target.
struct Crossfade {
  gpu::Image* other = nullptr;
  float weight = 0.0f;
  IsfTransition* transition = nullptr;
};

class SceneRenderer {
 public:
  SceneRenderer(const gpu::Device& device, gpu::ProgramLibrary& programs, const Assets& assets,
                uint32_t framesInFlight);
  ~SceneRenderer();

  // Creates the scene with `create` (the previous one is retired, not waited for); throws
  // vitrine::Error if its set-up fails. A scene of the registry is made by its own factory.
  void setScene(const SceneInfo& info, SceneFactory create);
  void setScene(const SceneInfo& info) { setScene(info, sceneFactory(info)); }
  Scene& scene() { return *scene_; }
  params::Bound parameters() { return scene_->parameters(); }
  // key=value pairs for the current scene, judged together (the scene's cross-parameter check runs
  // once on the final values); on failure nothing changes and the reason is returned.
  std::string applyParameters(const params::KeyValues& values);
  std::string applyPreset(std::string_view name);
  // How many times the current frame's work `change` would make it, from the scene's frameCost
  // (1 when the scene cannot tell, or the change would be refused anyway).
  double costRatio(const params::KeyValues& change);
  const SceneInfo& info() const { return *info_; }
  // Where scenes created from now on report their events (null: nowhere).
  void setEventSink(EventSink* sink) { events_ = sink; }
  // Where scenes created from now on play their sound (null: silence). It must outlive this renderer.
  void setAudioSink(audio::AudioSink* sink) { audio_ = sink ? sink : &silence_; }
  // Whether scenes created from now on run in real time (the gallery) or step by step (headless,
  // bench, tests), where anything they do on other threads must run in lock-step to stay reproducible.
  void setRealtime(bool realtime) { realtime_ = realtime; }
  gpu::PassTimer& timer() { return timer_; }
  // Whether the frames recorded from now on are seen (FrameContext::draws); record's frames before its
  // --range are simulated only.
  void setDrawing(bool drawing) { drawing_ = drawing; }
  // The flash guard the frames presented from now on go through (null: none). It belongs to the
  // output, not to this renderer: the gallery hands its one guard to whichever renderer is showing.
  void setFlashGuard(FlashGuard* guard) { guard_ = guard; }
  FlashGuard* flashGuard() const { return guard_; }

  void record(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, const BlitDestination& dst,
              const Crossfade& fade = {});
  // The scene into its target only, sized for an output of `output` (the incoming scene of a fade).
  void recordTarget(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, VkExtent2D output);
  // After record(): the same frame onto another output (a second projector), through its own warp.
  void recordOutput(VkCommandBuffer cmd, const BlitDestination& dst, const Crossfade& fade = {});
  // After record(): the target scaled onto `output` (an HDR image with storage or transfer-dst use)
  // as the present pass scaled it onto the window, left a transfer source. What F12 and F9 save.
  void recordScaled(VkCommandBuffer cmd, gpu::Image& output);
  // No scene any more: it and its images are retired behind the frames that used them.
  void clear();
  bool hasScene() const { return scene_ != nullptr; }
  gpu::Image& target() { return target_; }
  // The ISF filters after the scene (host/filters/filter_chain.h): made at first use, kept across
  // scenes until whoever sets them changes them; empty, they record nothing.
  FilterChain& filters();
  bool hasFilters() const { return filters_ && !filters_->empty(); }

 private:
  bool realtime_ = false;
  bool drawing_ = true;
  FlashGuard* guard_ = nullptr;
  void ensureTarget(VkExtent2D output);
  void blit(VkCommandBuffer cmd, const BlitDestination& dst);
  bool canPresent(const BlitDestination& dst) const;  // the compute path: else a blit
  // Once a frame, for the frame that is shown (a screenshot's copy is not): the guard's frame.
  gpu::Image& guardFrame(VkCommandBuffer cmd, const Crossfade& fade, double time);
  void present(VkCommandBuffer cmd, const BlitDestination& dst, gpu::Image& frame, const Crossfade& fade);
  const gpu::Device& device_;
  gpu::ProgramLibrary& programs_;
  const Assets& assets_;
  uint32_t framesInFlight_;
  gpu::PassTimer timer_;
  gpu::StreamArena stream_;
  std::array<gpu::ComputeProgram, 2> presents_;  // present.comp: [warped]
  const SceneInfo* info_ = nullptr;
  EventSink* events_ = nullptr;
  audio::SilentAudio silence_;
  audio::AudioSink* audio_ = &silence_;
  std::unique_ptr<gpu::FrameResources> resources_;
  std::unique_ptr<Scene> scene_;
  gpu::Image target_;
  gpu::Image* shown_ = nullptr;   // this frame's guarded frame, which every output shows; null: the target
  bool transitioned_ = false;     // this frame's transition is drawn into the target: no mix in the outputs
  std::unique_ptr<FilterChain> filters_;
  VkExtent2D sceneExtent_{0, 0};  // what the scene and its images were last sized for
};

}  // namespace vitrine::host
