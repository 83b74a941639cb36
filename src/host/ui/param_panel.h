#pragma once
// The parameter panel, drawn from a scene's schema with no per-parameter code: a widget chosen by
// kind (slider, checkbox, combo, text), tooltips from the help text, a reset per parameter and per
// scene, the scene's presets and the user's own (marked "yours"), which it saves, renames, deletes and
// exports through the caller. It never writes a value itself: every edit comes back as key=value
// pairs that the caller applies through the same validation as the command line.
#include "params/preset_store.h"
#include "params/schema.h"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace vitrine::host {

struct PanelEdit {
  // Preset applies one, built-in or the user's; the others act on the user's presets of the scene.
  enum class What { Values, Preset, ResetAll, SavePreset, RenamePreset, DeletePreset, ExportPreset } what = What::Values;
  params::KeyValues values;  // What::Values: the pairs to apply
  std::string preset;        // the preset's name (SavePreset: the name to save the current values as)
  std::string newName;       // RenamePreset: the name it takes
};
using UserPresets = std::vector<const params::UserPreset*>;

class ParamPanel {
 public:
  // Draws the panel for `bound`; returns what the user asked for this frame, if anything.
  // `tierInUse` ("auto: low") is shown as the quality choice when the scene says which tier it runs.
  // `mine`: the user's presets of the scene, listed after the scene's own.
  std::optional<PanelEdit> draw(const params::Bound& bound, std::string_view tierInUse = {}, const UserPresets& mine = {});
  void forget() {  // a scene switch
    editing_.clear();
    typing_.clear();
    clicked_.reset();
    naming_ = Naming::None;
  }
  // The parameter whose widget was last clicked (MIDI learn), once.
  std::optional<std::string> takeClicked() { return std::exchange(clicked_, std::nullopt); }

 private:
  // Values being dragged or typed in widgets that apply on release, by key.
  std::map<std::string, double> editing_;
  std::map<std::string, std::string> typing_;
  std::optional<std::string> clicked_;
  // The name being typed for "save as" or "rename", under the preset list.
  enum class Naming { None, SaveAs, Rename } naming_ = Naming::None;
  std::string renaming_;  // Rename: the preset's old name
  char name_[64] = {};
  bool focusName_ = false;
  std::optional<PanelEdit> drawUserPresetActions(const params::Bound& bound, const UserPresets& mine);
};

// The first of the schema's presets that the current values match (every value it sets is the value
// now), or null: the values are the user's own ("custom").
const params::Preset* matchingPreset(const params::Bound& bound);
// The first of the user's presets that the current values match, or null.
const params::UserPreset* matchingUserPreset(const params::Bound& bound, const UserPresets& mine);
// What the preset list shows: that preset's name ("NAME (yours)" for the user's), "defaults" when every
// value is its default, else "custom".
std::string presetLabel(const params::Bound& bound, const UserPresets& mine = {});

}  // namespace vitrine::host
