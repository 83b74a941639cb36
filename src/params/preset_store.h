#pragma once
// Presets people make: a scene's values saved under a name, beside the ones the scene ships. A preset
// file is small JSON,
//
//   {"version": 1, "scene": "kifs", "name": "evening", "values": {"step": 6, "tier": "low"}}
//
// with its values typed as the settings file types them and checked by the same code
// (checkSceneValues), so a value a preset may hold is exactly one the settings file may hold. Unlike
// settings, a preset is all or nothing: a value refused or a key this build does not know refuses the
// whole file, with a reason naming it, since a look with a value missing is another look.
//
// The store keeps one file per preset in a folder beside settings.json ("presets/kifs-evening.json"),
// not one presets.json: a preset is exported by writing that same file elsewhere and imported by
// reading one, a file broken by hand refuses itself and no other preset, and two galleries saving
// different presets never write the same file.
#include "params/settings_file.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::params {

inline constexpr int kPresetVersion = 1;
inline constexpr uintmax_t kMaxPresetBytes = 64u << 10;  // a preset is a few hundred bytes
inline constexpr size_t kMaxPresetName = 40;              // what the panel's list can show
inline constexpr size_t kMaxPresetsPerScene = 100;        // a list one can still read; every state message lists them

struct UserPreset {
  std::string scene;
  std::string name;
  KeyValues values;  // canonical text, ready for applyValues
  bool operator==(const UserPreset&) const = default;
};

// Why `name` cannot name a preset of a scene with `schema`: empty, longer than kMaxPresetName, not
// printable ASCII, blank at either end, holding '.' or '=' (which --preset
// SCENE.NAME could not tell apart), or one of the scene's own presets. Empty when it can.
std::string presetNameProblem(std::string_view name, const Schema& schema);

// Reads and checks one preset file; never throws. The preset, or why it is refused (a sentence naming
// the file).
struct PresetRead {
  std::optional<UserPreset> preset;
  std::string why;
};
PresetRead readPresetFile(const std::filesystem::path& path, const SchemaLookup& schemaFor);
// Writes the file a preset is (the store's format, which export writes too); throws vitrine::Error.
void writePresetFile(const std::filesystem::path& path, const UserPreset& preset, const SchemaLookup& schemaFor);

// The user's presets in one folder. Every operation returns why it did nothing (empty: done); none
// throws for what is on the disk.
class PresetStore {
 public:
  // `folder` empty: no folder to keep presets in; the list is empty and saving says so. Reads every
  // "*.json" in it; a refused file is one warning each and, with MoveBadAside (the gallery), moved
  // aside ("NAME.json.bad-..."); runs that only read presets leave it alone.
  PresetStore(std::filesystem::path folder, SchemaLookup schemaFor, LoadMode mode = LoadMode::MoveBadAside);

  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::filesystem::path& folder() const { return folder_; }
  // The scene's presets, by name.
  std::vector<const UserPreset*> presetsOf(std::string_view scene) const;
  const UserPreset* find(std::string_view scene, std::string_view name) const;

  // Saves `values` as a new preset, or over the user's own of that name. The values are checked first.
  std::string save(const UserPreset& preset);
  std::string rename(std::string_view scene, std::string_view from, std::string_view to);
  std::string remove(std::string_view scene, std::string_view name);
  // Writes the preset's file to `path`, which import reads back.
  std::string exportTo(std::string_view scene, std::string_view name, const std::filesystem::path& path) const;
  // Reads a preset file (checked as the store's own are) and saves it into the store.
  std::string import(const std::filesystem::path& path);

  // The file a preset is kept in: "SCENE-NAME.json", with any byte of the name other than a letter,
  // digit, '-' or '_' written as %XX so that every name has its own file.
  std::filesystem::path fileOf(std::string_view scene, std::string_view name) const;

 private:
  std::string check(const UserPreset& preset) const;
  std::filesystem::path folder_;
  SchemaLookup schemaFor_;
  std::vector<UserPreset> presets_;
  std::vector<std::string> warnings_;
};

}  // namespace vitrine::params
