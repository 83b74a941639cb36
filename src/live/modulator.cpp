#include "live/modulator.h"

#include "scenes/catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>
#include <cmath>

namespace vitrine::live {

float smooth(float previous, float target, float dt, float attack, float release) {
  const float tau = target > previous ? attack : release;
  if (!(tau > 0.0f)) return target;
  return previous + (target - previous) * (1.0f - std::exp(-dt / tau));
}

float applyCurve(Curve curve, float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  switch (curve) {
    case Curve::EaseIn: return x * x;
    case Curve::EaseOut: return 1.0f - (1.0f - x) * (1.0f - x);
    case Curve::Smooth: return x * x * (3.0f - 2.0f * x);
    case Curve::Linear:
    case Curve::Log: return x;  // log spreads the range geometrically instead (see target())
  }
  return x;
}

namespace {

// A parameter's number for text (the range's ends), read through its own parse on a scratch struct.
double numberOf(const params::Param& param, const params::Schema& schema, const std::string& text) {
  const auto scratch = schema.makeDefaults();
  param.parse(scratch.get(), text, nullptr);
  return param.number(scratch.get());
}

struct Target {
  std::string text;
  double number = 0.0;
  double span = 1.0;  // the range's width, for takeover's "close enough"
};

// The range a mapping spreads 0..1 over, as the parameter's numbers (choices: their indices).
std::pair<double, double> rangeOf(const Mapping& mapping, const params::Param& param, const params::Schema& schema) {
  const bool choice = param.kind == params::Kind::Choice;
  return {mapping.lo ? numberOf(param, schema, *mapping.lo) : choice ? 0.0 : param.min,
          mapping.hi ? numberOf(param, schema, *mapping.hi) : choice ? double(param.choices.size() - 1) : param.max};
}

// What the parameter becomes for a shaped value x in 0..1 over [lo, hi].
Target target(const Mapping& mapping, const params::Param& param, double lo, double hi, float x) {
  if (param.kind == params::Kind::Bool) return {x >= 0.5f ? "on" : "off", x >= 0.5f ? 1.0 : 0.0, 1.0};
  if (param.kind == params::Kind::Choice) {  // each choice of the range gets an equal share of 0..1
    const double steps = std::abs(hi - lo) + 1.0;
    const double offset = std::min(std::floor(double(x) * steps), steps - 1.0);
    const size_t index = size_t(lo <= hi ? lo + offset : lo - offset);
    return {param.choices[index], double(index), steps};
  }
  double value = mapping.curve == Curve::Log ? lo * std::pow(hi / lo, double(x)) : lo + (hi - lo) * double(x);
  value = std::clamp(value, std::min(lo, hi), std::max(lo, hi));
  if (param.kind == params::Kind::Int) {
    value = std::round(value);
    return {std::to_string(int(value)), value, std::abs(hi - lo)};
  }
  // Six significant digits: a mapped value reads as a person would type it ("1.15", not "1.1500001").
  const float rounded = float(std::stod(fmt::format("{:.6g}", value)));
  return {params::formatFloat(rounded), double(rounded), std::abs(hi - lo)};
}

}  // namespace

void Modulator::setMappings(const SceneInfo& scene, std::vector<Mapping> mappings) {
  scene_ = &scene;
  mappings_ = std::move(mappings);
  states_.assign(mappings_.size(), State{});
  // The range's ends are read once here, not every step (each read parses on a scratch settings struct).
  for (size_t i = 0; i < mappings_.size(); ++i)
    if (const params::Param* param = scene.schema().find(mappings_[i].target))
      std::tie(states_[i].lo, states_[i].hi) = rangeOf(mappings_[i], *param, scene.schema());
}

Modulated Modulator::step(const SourceBank& sources, const params::Bound& current, float dt) {
  Modulated out;
  if (!scene_) return out;
  const params::Schema& schema = *current.schema;
  for (size_t i = 0; i < mappings_.size(); ++i) {
    const Mapping& mapping = mappings_[i];
    State& state = states_[i];
    state.source = sources.value(mapping.source);
    const float previousShaped = state.shaped;
    const bool first = !state.smoothed;
    state.smoothed = first ? state.source : smooth(*state.smoothed, state.source, dt, mapping.attack, mapping.release);
    state.shaped = applyCurve(mapping.curve, *state.smoothed);

    if (scene_->findAction(mapping.target)) {
      state.engaged = true;
      if (!first && previousShaped < 0.5f && state.shaped >= 0.5f) out.actions.push_back({mapping.target, mapping.args});
      continue;
    }
    const params::Param* param = schema.find(mapping.target);
    if (!param) continue;  // checked when the mapping was made; a schema never loses a key
    const std::string now = param->format(current.settings);
    const Target aim = target(mapping, *param, state.lo, state.hi, state.shaped);
    if (mapping.takeoverMode() == Takeover::Soft) {
      if (state.engaged && now != state.written) state.engaged = false;  // someone else moved it
      if (!state.engaged) {
        const double value = param->number(current.settings);
        const bool close = std::abs(aim.number - value) <= 0.02 * std::max(aim.span, 1e-6);
        const bool crossed = state.lastTarget && (*state.lastTarget - value) * (aim.number - value) <= 0.0;
        state.engaged = close || crossed;
      }
      state.lastTarget = aim.number;
      if (!state.engaged) continue;
    } else {
      state.engaged = true;
    }
    state.written = aim.text;
    if (aim.text != now) {
      // A later mapping to the same key wins: keep one value per key.
      const auto same = std::find_if(out.values.begin(), out.values.end(), [&](const auto& kv) { return kv.first == mapping.target; });
      if (same != out.values.end()) same->second = aim.text;
      else out.values.emplace_back(mapping.target, aim.text);
    }
  }
  return out;
}

std::vector<MappingState> Modulator::states() const {
  std::vector<MappingState> out;
  for (size_t i = 0; i < mappings_.size(); ++i)
    out.push_back({formatMapping(mappings_[i]), states_[i].source, states_[i].shaped, states_[i].engaged});
  return out;
}

}  // namespace vitrine::live
