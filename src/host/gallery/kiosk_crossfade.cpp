#include "host/gallery/kiosk_crossfade.h"

#include <utility>

namespace vitrine::host {

SceneRenderer& KioskCrossfade::incoming() {
  if (!incoming_) incoming_ = make_();
  return *incoming_;
}

void KioskCrossfade::began(const FrameInput& run) {
  input_ = FrameInput{};
  input_.seed = run.seed;
  input_.reducedMotion = run.reducedMotion;
  shown_ = input_;
}

void KioskCrossfade::step() {
  if (!fading()) return;
  incoming_->scene().update(input_);
  shown_ = input_;
  input_.time += input_.dt;
  ++input_.frame;
}

Crossfade KioskCrossfade::record(VkCommandBuffer cmd, uint32_t slot, VkExtent2D frame) {
  if (!fading()) return {};
  incoming_->recordTarget(cmd, slot, shown_, frame);
  return {&incoming_->target(), weight_, transition_};
}

bool KioskCrossfade::finish(std::unique_ptr<SceneRenderer>& showing, FrameInput& input, FrameInput& shown) {
  if (!fading()) return false;
  std::swap(showing, incoming_);
  incoming_->clear();  // the scene that faded out
  input = input_;
  shown = shown_;
  return true;
}

void KioskCrossfade::cancel() {
  if (incoming_) incoming_->clear();
  weight_ = 0.0f;
}

}  // namespace vitrine::host
