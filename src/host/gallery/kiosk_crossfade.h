#pragma once
// Kiosk mode's cross-fade: the scene coming in runs in a second renderer, on its own clock and untouched
// by input, and its frame is mixed into the output by the fade's weight (the present pass's Crossfade)
// until the fade is over, when the renderers swap places. The timetable (host/gallery/kiosk_timetable.h) says
// when a fade begins and how far it is; this owns what it draws. An ISF transition (--transition),
// when set, draws the two frames together instead of the mix, at the fade's weight.
#include "frame/frame_input.h"
#include "host/scene_renderer.h"

#include <functional>
#include <memory>

namespace vitrine::host {

class KioskCrossfade {
 public:
  // Makes a renderer set up like the one showing (its sound, events and real time); called at the first
  // fade only, so a gallery that never fades holds no second renderer.
  using MakeRenderer = std::function<std::unique_ptr<SceneRenderer>()>;
  explicit KioskCrossfade(MakeRenderer make) : make_(std::move(make)) {}

  // Where the incoming scene is started (setScene, its values); then began().
  SceneRenderer& incoming();
  // The incoming scene started: its clock from zero, with the run's seed and reduced motion (`run`).
  void began(const FrameInput& run);
  bool fading() const { return incoming_ && incoming_->hasScene(); }
  float weight() const { return weight_; }
  void setTransition(IsfTransition* transition) { transition_ = transition; }
  void setWeight(float weight) { weight_ = weight; }
  // One simulation step of the incoming scene, as the showing scene takes one.
  void step();
  // The incoming scene's frame, sized for an output showing a frame of `frame` pixels, and what the
  // showing scene's present pass mixes it in by; no mix when nothing is coming in.
  Crossfade record(VkCommandBuffer cmd, uint32_t slot, VkExtent2D frame);
  // The fade is over: `showing` holds the scene that came in, `input` and `shown` its clock, and the
  // scene that faded out is retired. False, with nothing changed, when no scene was coming in.
  bool finish(std::unique_ptr<SceneRenderer>& showing, FrameInput& input, FrameInput& shown);
  // No fade (a scene chosen directly during one): the incoming scene retired, the weight 0.
  void cancel();

 private:
  MakeRenderer make_;
  std::unique_ptr<SceneRenderer> incoming_;
  FrameInput input_;  // the incoming scene's next step
  FrameInput shown_;  // its last step: what its frame shows
  float weight_ = 0.0f;
  IsfTransition* transition_ = nullptr;
};

}  // namespace vitrine::host
