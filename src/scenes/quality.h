#pragma once
// Quality tiers for every scene, and the automatic tier that holds a GPU frame-time target in the
// gallery: step down after a run of slow frames, up after a longer run of fast ones. Each scene
// declares the two parameters with addQualityParams and says what a tier means for it (a render scale,
// a march budget, how many strands it draws); AdaptiveQuality (scenes/adaptive_quality.h) picks the
// tier in use. Plain C++: the settings files that include it need no GPU code.
#include "params/schema.h"
#include "params/schema_impl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
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
  // `start`: where the search begins. A software device (lavapipe) starts low and steps up while its
  // frames are fast, rather than showing seconds of frozen high-tier frames before stepping down.
  explicit AutoTier(Tier start = Tier::High) : current_(start == Tier::Auto ? Tier::High : start) {}
  // Feeds one frame's GPU time; returns the tier to use next.
  Tier observe(double gpuMs, double targetMs) {
    if (gpuMs <= 0.0) return current_;
    // Frames of seconds (noodles' high tier on a CPU device) must not wait out eight of themselves:
    // two in a row far over the target step down at once, to the lowest tier when eight times over.
    // One alone (a shader compiling, a scene starting) is a hitch, not a verdict.
    if (gpuMs > targetMs * 4.0 && current_ != Tier::Low) {
      if (++farOver_ >= 2) {
        current_ = gpuMs > targetMs * 8.0 ? Tier::Low : Tier(int(current_) + 1);
        farOver_ = slow_ = fast_ = 0;
      }
      return current_;
    }
    farOver_ = 0;
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
  uint32_t slow_ = 0, fast_ = 0, farOver_ = 0;
};

// A render scale per tier, the common case: high 1, medium 0.7, low 0.5 (a quarter of the pixels).
inline float tierScale(Tier tier) { return tier == Tier::Low ? 0.5f : tier == Tier::Medium ? 0.7f : 1.0f; }

// What a tier keeps of a count a frame's cost grows with (a lattice's side, chains, wavelengths): all of
// it at high (and auto, resolved before it gets here), `medium` and `low` shares of it below, rounded to
// a multiple of `step`, never under `fewest` nor over the count itself.
struct TierShares {
  double medium = 0.75, low = 0.5;
};
inline int tierCount(int count, Tier tier, int fewest, TierShares shares = {}, int step = 1) {
  if (tier != Tier::Medium && tier != Tier::Low) return count;
  const double share = tier == Tier::Low ? shares.low : shares.medium;
  const int kept = int(std::lround(count * share / step)) * step;
  return std::clamp(kept, std::min(fewest, count), count);
}

}  // namespace vitrine
