#pragma once
// Quality tiers for every scene, and the automatic tier that holds a GPU frame-time target in the
// gallery: step down after a run of slow frames, up after a longer run of fast ones. Each scene
// declares the two parameters with addQualityParams and says what a tier means for it (a render scale,
// a march budget, how many strands it draws). Headless, bench and record runs are reproducible, so
// there "auto" is the high tier, whatever the frame times.
#include "params/schema.h"
#include "params/schema_impl.h"
#include "scenes/scene.h"

#include <fmt/format.h>

#include <cstdint>
#include <string>

namespace vitrine {

enum class Tier { Auto, High, Medium, Low };

// The tier parameter ("quality") and its frame-time target ("target_ms"), declared the same way in
// every scene's schema. S has the fields `Tier tier` and `float targetMs`.
template <typename S>
void addQualityParams(params::Schema& schema, std::string_view whatATierChanges, float targetMs) {
  schema.add(params::choiceParam<S>({"tier", "quality", std::string(whatATierChanges) + "; auto holds target_ms.", "quality"},
                                    &S::tier, {"auto", "high", "medium", "low"}));
  schema.add(params::floatParam<S>({"target_ms", "target GPU ms",
                                    fmt::format("The GPU frame time the auto tier holds (default {:g} ms).", targetMs),
                                    "quality", params::kLogarithmic},
                                   &S::targetMs, 1.0, 200.0));
}

class AutoTier {
 public:
  // Feeds one frame's GPU time; returns the tier to use next.
  Tier observe(double gpuMs, double targetMs) {
    if (gpuMs <= 0.0) return current_;
    if (gpuMs > targetMs * 1.1) {
      fast_ = 0;
      if (++slow_ >= 8 && current_ != Tier::Low) current_ = Tier(int(current_) + 1), slow_ = 0;
    } else if (gpuMs < targetMs * 0.5) {
      slow_ = 0;
      if (++fast_ >= 60 && current_ != Tier::High) current_ = Tier(int(current_) - 1), fast_ = 0;
    } else {
      slow_ = fast_ = 0;
    }
    return current_;
  }
  Tier current() const { return current_; }

 private:
  Tier current_ = Tier::High;
  uint32_t slow_ = 0, fast_ = 0;
};

// What a scene keeps: the tier in use, from its setting and, for auto in the gallery, the frame times.
class AdaptiveQuality {
 public:
  explicit AdaptiveQuality(const SceneContext& context) : events_(context.events), realtime_(context.realtime) {}

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

// A render scale per tier, the common case: high 1, medium 0.7, low 0.5 (a quarter of the pixels).
inline float tierScale(Tier tier) { return tier == Tier::Low ? 0.5f : tier == Tier::Medium ? 0.7f : 1.0f; }

}  // namespace vitrine
