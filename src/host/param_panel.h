#pragma once
// The parameter panel, drawn from a scene's schema with no per-parameter code: a widget chosen by
// kind (slider, checkbox, combo, text), tooltips from the help text, a reset per parameter and per
// scene, the scene's presets. It never writes a value itself: every edit comes back as key=value
// pairs that the caller applies through the same validation as the command line.
#include "params/schema.h"

#include <map>
#include <optional>
#include <string>

namespace vitrine::host {

struct PanelEdit {
  enum class What { Values, Preset, ResetAll } what = What::Values;
  params::KeyValues values;  // What::Values: the pairs to apply
  std::string preset;        // What::Preset: its name
};

class ParamPanel {
 public:
  // Draws the panel for `bound`; returns what the user asked for this frame, if anything.
  // `error` is the last rejected edit's reason, shown under the widgets.
  std::optional<PanelEdit> draw(const params::Bound& bound, const std::string& error);
  void forget() {  // a scene switch
    editing_.clear();
    typing_.clear();
  }

 private:
  // Values being dragged or typed in widgets that apply on release, by key.
  std::map<std::string, double> editing_;
  std::map<std::string, std::string> typing_;
};

}  // namespace vitrine::host
