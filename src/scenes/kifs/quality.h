#pragma once
// Quality tiers (march budget and render scale) and the automatic tier that holds a GPU frame-time
// target: step down after a run of slow frames, up after a longer run of fast ones.
#include <cstdint>

namespace vitrine::kifs {

enum class Tier { Auto, High, Medium, Low };

struct TierSettings {
  int marchSteps;
  float renderScale;
};

inline TierSettings settingsFor(Tier tier) {
  switch (tier) {
    case Tier::Medium: return {56, 0.66f};
    case Tier::Low: return {40, 0.5f};
    default: return {90, 1.0f};
  }
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

}  // namespace vitrine::kifs
