#include "live/source_bank.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

namespace vitrine::live {

float lfoValue(std::string_view name, double seconds) {
  // lfo.SHAPE.PERIOD: the period may hold a '.' of its own (lfo.sine.0.5).
  if (!name.starts_with("lfo.")) return 0.0f;
  const size_t dot = name.find('.', 4);
  if (dot == std::string_view::npos) return 0.0f;
  const std::string_view shape = name.substr(4, dot - 4), periodText = name.substr(dot + 1);
  double period = 0.0;
  const auto [end, ec] = std::from_chars(periodText.data(), periodText.data() + periodText.size(), period);
  if (ec != std::errc() || end != periodText.data() + periodText.size() || !(period > 0.0)) return 0.0f;
  const double phase = seconds / period - std::floor(seconds / period);
  if (shape == "sine") return float(0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * phase));
  if (shape == "triangle") return float(1.0 - std::abs(1.0 - 2.0 * phase));
  if (shape == "saw") return float(phase);
  if (shape == "square") return phase < 0.5 ? 1.0f : 0.0f;
  return 0.0f;
}

void SourceBank::set(std::string_view name, float value) {
  value = std::isnan(value) ? 0.0f : std::clamp(value, 0.0f, 1.0f);
  if (auto found = values_.find(name); found != values_.end()) {
    found->second = value;
    Use& use = uses_.find(name)->second;
    auto& order = use.read ? read_ : unread_;
    auto entry = order.extract(use.written);
    entry.key() = use.written = ++writes_;
    order.insert(std::move(entry));
    return;
  }
  if (values_.size() >= kMaxSourceNames) forgetOne();
  values_.emplace(std::string(name), value);
  uses_.emplace(std::string(name), Use{++writes_, false});
  unread_.emplace(writes_, std::string(name));
}

void SourceBank::forgetOne() {
  auto& order = unread_.empty() ? read_ : unread_;
  const auto oldest = order.begin();
  values_.erase(oldest->second);
  uses_.erase(oldest->second);
  order.erase(oldest);
}

float SourceBank::value(std::string_view name) const {
  if (name.starts_with("lfo.")) return lfoValue(name, time_);
  const auto found = values_.find(name);
  if (found == values_.end()) return 0.0f;
  if (Use& use = uses_.find(name)->second; !use.read) {
    use.read = true;
    read_.insert(unread_.extract(use.written));
  }
  return found->second;
}

}  // namespace vitrine::live
