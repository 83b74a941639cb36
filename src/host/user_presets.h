#pragma once
// Where the user's presets (params/preset_store.h) meet the runs: the folder they are kept in, finding
// a preset by name among a scene's own and the user's, and the presets a run's command line asks for.
//
// A name is looked up among the scene's own presets first, then the user's. The two never share a
// name (saving refuses a built-in name, and a file that takes one is refused when read), so the order
// only means that a run naming a built-in preset never reads the user's files: goldens and benchmarks
// do not depend on them.
#include "app/options.h"
#include "params/preset_store.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

// "presets" beside the settings file ($XDG_CONFIG_HOME/vitrine/presets); empty when there is no
// settings folder.
std::filesystem::path userPresetFolder();
// The folder above, read now; its warnings are the caller's to show. Only the gallery moves bad files
// aside: a run that only reads presets leaves them as they are.
params::PresetStore openUserPresets(params::LoadMode mode = params::LoadMode::LeaveAlone);

// `name` among the scene's own presets, then `store`'s (null: the user's, read only if needed). Empty
// values and the reason ("kifs has no preset 'x'; its presets: sphere final; yours: evening") when
// neither has it.
struct FoundPreset {
  std::optional<params::Preset> preset;
  std::string why;
};
FoundPreset findPreset(std::string_view scene, std::string_view name, const params::PresetStore* store = nullptr);

// The presets of --preset-file files whose scene is `scene` (a file for another scene is left unused,
// as SCENE.KEY=VALUE is). Throws vitrine::Error for a refused file.
std::vector<params::Preset> presetFilesFor(const Options& options, std::string_view scene);
// The presets a run applies to `scene`, in command-line order: each --preset naming it (SCENE.NAME, or
// NAME when `unqualifiedToo`), then each --preset-file whose scene it is. Throws vitrine::Error for an
// unknown name or a refused file.
std::vector<params::Preset> presetsForRun(const Options& options, std::string_view scene, bool unqualifiedToo);

// --save-preset: a headless run's final values (transient ones left out) saved as the user's preset.
// Throws vitrine::Error with the store's reason.
void saveRunPreset(const Options& options, const params::Bound& bound);
int runExportPreset(const Options& options);  // --export-preset [SCENE.]NAME --out FILE.json

}  // namespace vitrine::host
