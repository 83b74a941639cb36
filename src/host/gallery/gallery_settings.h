#pragma once
// Each scene's parameter values across a gallery session: read from the settings file at start,
// given to a scene whenever it is created (so switching away and back keeps its values), updated
// after every change, and written back — debounced while a slider moves, flushed on exit. Headless,
// bench and record runs never use this: goldens and benchmarks cannot depend on a user's file.
#include "params/settings_file.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

class GallerySettings {
 public:
  using Clock = params::SettingsSaver::Clock;

  // `path` empty: nothing is read or written. `reset`: start from defaults (the file is rewritten on
  // the first change). Problems with the file become warnings(), never errors. `keepScene` (kiosk
  // mode): the scene to start with is the gallery's to choose; showing() leaves it as it is.
  GallerySettings(std::filesystem::path path, bool reset, bool keepScene = false);
  ~GallerySettings();  // flushes

  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::string& lastScene() const { return settings_.scene; }
  const std::filesystem::path& path() const { return path_; }

  // What a scene starts with: its saved values (validated key by key when loaded).
  params::KeyValues valuesFor(std::string_view scene) const;
  // After any change, or when a scene is left: its current values (all of them, transient ones too,
  // so a switch back restores them; only non-transient ones are written). Saving merges with the
  // file as it is then, key by key: only keys whose value this gallery changed (a missing key counts
  // as its default) are written over what another gallery on the same file may have saved.
  void remember(std::string_view scene, params::KeyValues values, Clock::time_point now);
  void showing(std::string_view scene, Clock::time_point now);  // the scene to start with next time
  // Live input: the user's own mapping lines per scene, and whether audio input is on, from which device.
  const std::vector<std::string>& mappingsFor(std::string_view scene) const;
  void setMappings(std::string_view scene, std::vector<std::string> lines, Clock::time_point now);
  bool audioInput() const { return settings_.audioInput; }
  const std::string& audioDevice() const { return settings_.audioDevice; }
  void setAudioInput(bool on, std::string device, Clock::time_point now);
  // Outputs: each one's warp as the file keeps it (null when it has none), checked by whoever applies
  // it; an empty (identity) warp removes the entry.
  const nlohmann::ordered_json* warpFor(std::string_view output) const;
  // The lights' patch the settings file names ({"lights": {"patch": FILE}}, docs/LIGHTS.md); empty: none.
  std::string lightsPatch() const;
  void setWarp(std::string_view output, nlohmann::ordered_json warp, Clock::time_point now);
  // ISF filters: each scene's chain as the file keeps it (an array of {"file", "values"}; null when it has
  // none), checked by whoever applies it; an empty array removes the entry.
  const nlohmann::ordered_json* filtersFor(std::string_view scene) const;
  void setFilters(std::string_view scene, nlohmann::ordered_json chain, Clock::time_point now);
  // The transition of scene switches ({"file", "values"}; null: none), checked by whoever applies it.
  const nlohmann::ordered_json& transition() const { return settings_.transition; }
  void setTransition(nlohmann::ordered_json transition, Clock::time_point now);
  void tick(Clock::time_point now);  // writes when a burst of changes has settled
  void flush();                      // writes now if anything is unsaved

 private:
  void save();
  std::filesystem::path path_;
  bool keepScene_ = false;
  params::Settings settings_;
  params::SettingsChanges changes_;  // since the last save
  params::SettingsSaver saver_;
  std::vector<std::string> warnings_;
};

}  // namespace vitrine::host
