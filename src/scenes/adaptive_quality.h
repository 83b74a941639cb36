#pragma once
// What a scene keeps to pick its quality tier each step: its setting, or for "auto" in the gallery the
// automatic tier fed with the last frame's GPU time (starting low on a software device). Headless, bench and record runs are reproducible,
// so there "auto" is the high tier, whatever the frame times.
#include "gpu/device.h"
#include "scenes/quality.h"
#include "scenes/scene.h"

#include <string>

namespace vitrine {

// What a scene keeps: the tier in use, from its setting and, for auto in the gallery, the frame times.
class AdaptiveQuality {
 public:
  explicit AdaptiveQuality(const SceneContext& context)
      : events_(context.events), realtime_(context.realtime), auto_(startingTier(context.device)) {}
  // In the gallery, auto starts at the low tier on a CPU device (lavapipe, SwiftShader), else high.
  static Tier startingTier(const gpu::Device& device) {
    return device.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? Tier::Low : Tier::High;
  }

  // Once per step with the scene's settings; reports a change of the automatic tier as a "tier" event.
  void update(Tier setting, float targetMs, const FrameInput& input) {
    setting_ = setting;
    if (setting != Tier::Auto || !realtime_) return;
    const Tier before = auto_.current();
    if (const Tier now = auto_.observe(input.lastGpuMs, targetMs); now != before)
      events_.emit(input.time, {"tier", {{"from", name(before)}, {"to", name(now)}, {"gpu_ms", input.lastGpuMs}}});
  }
  Tier active() const { return setting_ != Tier::Auto ? setting_ : realtime_ ? auto_.current() : Tier::High; }
  // "auto: medium" or "high", for a scene's panel read-out.
  std::string describe() const { return setting_ == Tier::Auto ? "auto: " + name(active()) : name(active()); }
  static std::string name(Tier tier) {
    static const char* names[] = {"auto", "high", "medium", "low"};
    return names[int(tier)];
  }

 private:
  SceneEvents events_;
  bool realtime_;
  Tier setting_ = Tier::Auto;
  AutoTier auto_;
};

}  // namespace vitrine
