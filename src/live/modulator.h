#pragma once
// Turns sources into a scene's values, once a simulation step: each mapping's source is smoothed,
// shaped by its curve, spread over its range and written as the parameter's canonical text, which the
// host applies through the schema exactly as --set (so every check holds). Actions fire as their
// source rises through one half. Pure logic over a SourceBank: no devices, no GPU.
#include "frame/frame_input.h"
#include "live/mapping.h"
#include "live/source_bank.h"
#include "params/schema.h"

#include <optional>
#include <string>
#include <vector>

namespace vitrine::live {

struct Modulated {
  params::KeyValues values;          // parameters whose text changes this step, in mapping order
  std::vector<ActionCall> actions;   // actions fired this step
};

// What the panel and the remote page show of one mapping.
struct MappingState {
  std::string text;     // formatMapping's line
  float source = 0.0f;  // the source now, 0..1
  float shaped = 0.0f;  // after smoothing and curve, 0..1
  bool engaged = true;  // soft takeover: false until the control meets the parameter's value
};

class Modulator {
 public:
  // The mappings that drive `scene` from now on (each already checked with checkMapping); state restarts.
  void setMappings(const SceneInfo& scene, std::vector<Mapping> mappings);
  const std::vector<Mapping>& mappings() const { return mappings_; }

  // One step of `dt` seconds: the values and actions the sources ask of the scene whose live values
  // are `current`. A value equal to the current text is left out; a parameter someone else changed
  // (the panel, --set, remote) disengages a soft-takeover mapping until its control meets the value again.
  Modulated step(const SourceBank& sources, const params::Bound& current, float dt);
  std::vector<MappingState> states() const;

 private:
  struct State {
    std::optional<float> smoothed;     // none before the first step
    float shaped = 0.0f;
    float source = 0.0f;
    std::optional<double> lastTarget;  // the value it last aimed at, as a number (takeover)
    std::string written;               // the text it last wrote ("" before)
    bool engaged = false;
    double lo = 0.0, hi = 1.0;         // the range as the parameter's numbers, read at setMappings
  };
  const SceneInfo* scene_ = nullptr;
  std::vector<Mapping> mappings_;
  std::vector<State> states_;
};

// The shaping stages, exposed for tests: one-pole smoothing toward `target` over `dt` with time
// constant `attack` when rising, `release` when falling; then the curve on 0..1.
float smooth(float previous, float target, float dt, float attack, float release);
float applyCurve(Curve curve, float x);

}  // namespace vitrine::live
