#pragma once
// The gallery's settings file: the scene it last showed and every scene's saved values, e.g.
//
//   {"version": 1, "scene": "noodles",
//    "scenes": {"kifs": {"step": 9, "tier": "high"}, "noodles": {"grid": "32x32x8", "msaa": "4x"}},
//    "mappings": {"kifs": ["midi.cc.1.21=kifs.fold:0.9:1.2"]},
//    "live": {"audio_input": true, "audio_device": ""},
//    "outputs": {"main": {"corners": [[0.02, 0], [1, 0.04], [0.97, 1], [0, 0.96]]}, "HDMI-1": {"turn": 180}},
//    "filters": {"kifs": [{"file": "invert.fs", "values": {"amount": 0.5}}]},
//    "transition": {"file": "wipe.fs", "values": {"softness": 0.2}}}
//
// Mappings (live/mapping.h) are kept here as their lines of text, and each output's warp (projector
// setup's corner pin, its turn, region and soft edges; host/present/output_warp_file.h) as its JSON object,
// each scene's ISF filter chain (host/filters/filter_chain.h) as its JSON array and the gallery's ISF
// transition as its JSON object; whoever applies them checks them, as values are checked by their parse.
//
// Values are typed by kind (Float/Int: numbers, Bool: true/false, Choice/Custom: strings) and every
// one is validated by the parameter's own parse, as --set values are. A file is the user's: nothing in
// it is deleted. Values this version does not understand are kept and written back; a file that cannot
// be read as settings is renamed aside, and the gallery starts from the defaults.
#include "core/bounded_file.h"
#include "params/schema.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::params {

inline constexpr int kSettingsVersion = 1;
inline constexpr uintmax_t kMaxSettingsBytes = 1u << 20;  // a settings file is a few kB; more is not one

// $XDG_CONFIG_HOME/vitrine/settings.json, else $HOME/.config/vitrine/settings.json (a relative
// XDG_CONFIG_HOME is ignored, as the XDG Base Directory spec says). Empty when neither is usable: the
// gallery then keeps no settings.
std::filesystem::path defaultSettingsPath();

struct Settings {
  std::string scene;                         // the scene to start with; empty: the gallery's default
  std::map<std::string, KeyValues> scenes;   // per scene: canonical key=value text, ready for applyValues
  std::map<std::string, std::vector<std::string>> mappings;  // per scene: the user's mapping lines
  bool audioInput = false;                   // live audio input on (the scenes' audio mappings play)
  std::string audioDevice;                   // the capture device; empty: the default output's monitor
  std::map<std::string, nlohmann::ordered_json> outputs;  // per output name: its warp as JSON (an object)
  std::map<std::string, nlohmann::ordered_json> filters;  // per scene: its filter chain as JSON (an array)
  nlohmann::ordered_json transition;  // the scene switches' ISF transition as JSON (an object); null: none
  // Everything read but not understood, in the file's own shape (top-level keys, scenes this version
  // does not have, unknown keys inside known scenes); saveSettings writes it back underneath.
  nlohmann::ordered_json unknown = nlohmann::ordered_json::object();
};

struct LoadResult {
  Settings settings;
  std::vector<std::string> warnings;  // one sentence each, for the log or the overlay
  bool readable = true;               // false: the file was there but is not settings (see loadSettings)
};

// What a reader does with a file that is not settings: the gallery at start moves it aside and starts
// from the defaults; a save that merges with the file on disk moves it aside and writes the gallery's
// values in its place (the file was edited into something else while the gallery ran); a reader that
// only looks leaves it.
enum class LoadMode { MoveBadAside, ReplaceBad, LeaveAlone };

// Returns a scene's schema, or null for a scene this build does not have. A scene without parameters
// should return an empty schema, not null.
using SchemaLookup = std::function<const Schema*(std::string_view scene)>;

// Never throws for what is in or around the file: every problem is a warning and the defaults apply.
// A bad value is dropped (one warning naming scene, key and why); a file that is not settings (not
// JSON, not an object, another version, over kMaxSettingsBytes, nested deeper than any settings file)
// is renamed to "settings.json.bad-YYYYMMDD-HHMMSS" beside it; a missing file is no warning. Every
// other failure to read a regular file (cannot open it, a number out of range such as 1e400 anywhere
// in it, any exception while reading) ends the same way: one warning, moved aside, the defaults.
// Values are checked one by one on a default struct: a scene's cross-parameter check is for whoever
// applies them (applyValues with the scene's check).
LoadResult loadSettings(const std::filesystem::path& path, const SchemaLookup& schemaFor,
                        LoadMode mode = LoadMode::MoveBadAside);

// Creates the folder and replaces the file atomically; throws vitrine::Error on failure. Transient
// parameters are left out; the schema gives each value its JSON type (a key no schema knows is
// written as a string). A path that is a symbolic link (a settings file kept in a dotfiles folder)
// stays one: the file it points to is replaced, beside itself.
void saveSettings(const std::filesystem::path& path, const Settings& settings, const SchemaLookup& schemaFor);

// The file `path` names once its symbolic links are followed (relative ones from the link's folder);
// `path` itself when it is no link. The last link may dangle: its target is where a save creates the
// file. Throws vitrine::Error for a loop of links.
std::filesystem::path resolveLinks(const std::filesystem::path& path);

// What one gallery changed since its last save, so that two galleries on one file do not undo each
// other: only these are written over what is on disk.
struct SettingsChanges {
  bool all = false;    // write everything (--reset-settings: the file starts over)
  bool scene = false;  // the scene to start with
  std::map<std::string, std::set<std::string>> keys;  // per scene, the keys changed (or removed)
  std::set<std::string> mappings;  // scenes whose mapping lines changed (written whole)
  bool live = false;               // audio input on/off or its device
  std::set<std::string> outputs;   // outputs whose warp changed (written whole)
  std::set<std::string> filters;   // scenes whose filter chain changed (written whole)
  bool transition = false;         // the transition or its values
  bool empty() const {
    return !all && !scene && keys.empty() && mappings.empty() && !live && outputs.empty() && filters.empty() &&
           !transition;
  }
};
// `disk` (the file as it is now) with `ours` written over it where `changed` says, key by key; a
// changed key `ours` no longer holds is removed. Everything else on disk stays as the other writer
// left it, unknown keys included.
Settings mergeSettings(Settings disk, const Settings& ours, const SettingsChanges& changed);

// What every reader of the user's own JSON files (settings, user presets) shares, so that each file is
// judged by one set of rules.
//
// Why a file is not one of ours (not a regular file, too large, not JSON, nested too deep, the wrong
// shape): thrown by readJsonFile and by the callers' own shape checks, caught where the file is judged.
using vitrine::FileRefused;
// The JSON in `path`, at most `maxBytes` long and nested no deeper than any of our files; throws
// FileRefused with the reason (never quoting the file's bytes, which may be binary).
nlohmann::ordered_json readJsonFile(const std::filesystem::path& path, uintmax_t maxBytes);
// Renames a refused file to "NAME.bad-YYYYMMDD-HHMMSS" beside it (then "-2", "-3" if taken), kept for a
// look; returns what happened, as a clause ("moved it to ...", "could not be moved aside (...)").
std::string moveAside(const std::filesystem::path& path);
// Writes `json` (indented, one trailing newline) atomically, creating the folder; a symbolic link
// stays one. Throws vitrine::Error.
void writeJsonFile(const std::filesystem::path& path, const nlohmann::ordered_json& json);

// One value that a scene's schema refused: its key, its JSON (cut short) and why.
struct ValueProblem {
  std::string key, value, why;
};
// One scene's values as the settings file holds them (an object of typed values), each checked by its
// parameter's own parse on a default struct exactly as "--set key=text" is: the canonical text of each
// good value is appended to `kept`, keys the schema does not know are copied into `unknown`, and every
// refused value (a wrong JSON type, out of range, transient) is returned.
std::vector<ValueProblem> checkSceneValues(const nlohmann::ordered_json& values, const Schema& schema,
                                           KeyValues& kept, nlohmann::ordered_json& unknown);

// A value as the settings file and the benchmark's JSON write it: Float/Int as numbers, Bool as
// true/false, the rest (and a key no schema knows: param null) as its text.
nlohmann::ordered_json typedValue(const Param* param, const std::string& text);
// Every parameter of a live scene as one JSON object, typed as above.
nlohmann::ordered_json valuesJson(const Bound& bound, bool includeTransient = true);

// Saved values that a scene's cross-parameter check refuses together (each was valid alone): keep
// what fits, drop only what conflicts. `apply` is the scene's batch apply (applyValues with its check,
// SceneRenderer::applyParameters): it changes nothing and returns why when it refuses. Tries all of
// them; then all but one, each in turn from the last (a later value is the likelier newcomer); then
// one by one in order, keeping each that fits with those kept before.
struct FittedValues {
  KeyValues kept;                    // applied
  std::vector<std::string> dropped;  // "key=value", in the file's order
  std::string why;                   // the check's reason for refusing them all together
};
FittedValues applyWhatFits(const KeyValues& values, const std::function<std::string(const KeyValues&)>& apply);

// When to save: after the values stop changing for `delay`, so a dragged slider writes once, after it
// settles. Pure logic; the caller passes the time and does the writing.
class SettingsSaver {
 public:
  using Clock = std::chrono::steady_clock;
  explicit SettingsSaver(Clock::duration delay = std::chrono::seconds(1)) : delay_(delay) {}

  void markDirty(Clock::time_point now);  // a value changed: (re)starts the wait
  // True once per burst of changes, when `delay` has passed since the last; the caller then saves. A
  // failed save can markDirty(now) again to retry after another delay.
  bool due(Clock::time_point now);
  // True when there are unsaved changes, however recent, and forgets them: for quitting or switching.
  bool flush();
  bool dirty() const { return dirty_; }

 private:
  Clock::duration delay_;
  Clock::time_point lastChange_{};
  bool dirty_ = false;
};

}  // namespace vitrine::params
