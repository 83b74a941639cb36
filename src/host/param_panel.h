#pragma once
// The parameter panel, drawn from a scene's schema with no per-parameter code: a widget chosen by
// kind (slider, checkbox, combo, text), tooltips from the help text, a reset per parameter and per
// scene, the scene's presets. It never writes a value itself: every edit comes back as key=value
// pairs that the caller applies through the same validation as the command line.
#include "params/schema.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace vitrine::host {

struct PanelEdit {
  enum class What { Values, Preset, ResetAll } what = What::Values;
  params::KeyValues values;  // What::Values: the pairs to apply
  std::string preset;        // What::Preset: its name
};

class ParamPanel {
 public:
  // Draws the panel for `bound`; returns what the user asked for this frame, if anything.
  // `tierInUse` ("auto: low") is shown as the quality choice when the scene says which tier it runs.
  std::optional<PanelEdit> draw(const params::Bound& bound, std::string_view tierInUse = {});
  void forget() {  // a scene switch
    editing_.clear();
    typing_.clear();
    clicked_.reset();
  }
  // The parameter whose widget was last clicked (MIDI learn), once.
  std::optional<std::string> takeClicked() { return std::exchange(clicked_, std::nullopt); }

 private:
  // Values being dragged or typed in widgets that apply on release, by key.
  std::map<std::string, double> editing_;
  std::map<std::string, std::string> typing_;
  std::optional<std::string> clicked_;
};

// The first of the schema's presets that the current values match (every value it sets is the value
// now), or null: the values are the user's own ("custom").
const params::Preset* matchingPreset(const params::Bound& bound);
// What the preset list shows: that preset's name, "defaults" when every value is its default, else
// "custom".
std::string presetLabel(const params::Bound& bound);

}  // namespace vitrine::host
