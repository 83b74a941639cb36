#pragma once
// Which quality tier "auto" picked, for the menu: the scenes' AdaptiveQuality reports each change as a
// "tier" event (from, to); a scene made afresh starts at the device's starting tier
// (AdaptiveQuality::startingTier: low on a CPU device, else high), which no event reports.
#include "params/schema.h"
#include "scenes/scene_events.h"

#include <map>
#include <string>
#include <string_view>
#include <utility>

namespace vitrine::host {

class TierWatch final : public EventSink {
 public:
  explicit TierWatch(std::string startingTier = "high") : start_(std::move(startingTier)) {}
  void setStartingTier(std::string tier) { start_ = std::move(tier); }
  void emit(double /*time*/, std::string_view scene, const SceneEvent& event) override {
    if (event.name != "tier") return;
    if (const EventValue* to = event.find("to"))
      if (const auto* name = std::get_if<std::string>(&to->value)) tiers_[std::string(scene)] = *name;
  }
  void started(std::string_view scene) { tiers_.erase(std::string(scene)); }
  // "auto: low" while the scene's tier parameter is auto; empty when it names a tier itself (or has none).
  std::string describe(std::string_view scene, const params::KeyValues& values) const {
    for (const auto& [key, value] : values)
      if (key == "tier") {
        if (value != "auto") return {};
        const auto it = tiers_.find(scene);
        return "auto: " + (it == tiers_.end() ? start_ : it->second);
      }
    return {};
  }

 private:
  std::string start_;
  std::map<std::string, std::string, std::less<>> tiers_;
};

}  // namespace vitrine::host
