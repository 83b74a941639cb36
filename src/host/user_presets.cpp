#include "host/user_presets.h"

#include "core/error.h"
#include "core/printable.h"
#include "scenes/catalogue.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

namespace vitrine::host {

std::filesystem::path userPresetFolder() {
  const std::filesystem::path settings = params::defaultSettingsPath();
  return settings.empty() ? std::filesystem::path() : settings.parent_path() / "presets";
}

params::PresetStore openUserPresets(params::LoadMode mode) {
  return params::PresetStore(userPresetFolder(), findSchema, mode);
}

FoundPreset findPreset(std::string_view scene, std::string_view name, const params::PresetStore* store) {
  const params::Schema* schema = findSchema(scene);
  if (!schema) return {std::nullopt, fmt::format("no scene '{}'", printable(scene))};
  if (const params::Preset* builtIn = schema->findPreset(name)) return {*builtIn, {}};
  std::optional<params::PresetStore> own;
  if (!store) store = &own.emplace(openUserPresets());
  if (const params::UserPreset* mine = store->find(scene, name)) return {params::Preset{mine->name, {}, mine->values}, {}};
  std::vector<std::string> builtIn, yours;
  for (const params::Preset& preset : schema->presets()) builtIn.push_back(preset.name);
  for (const params::UserPreset* preset : store->presetsOf(scene)) yours.push_back(fmt::format("'{}'", preset->name));
  return {std::nullopt,
          fmt::format("{} has no preset '{}'; its presets: {}; yours: {}", scene, printable(name),
                      builtIn.empty() ? "none" : fmt::format("{}", fmt::join(builtIn, " ")),
                      yours.empty() ? "none" : fmt::format("{}", fmt::join(yours, " ")))};
}

std::vector<params::Preset> presetsForRun(const Options& options, std::string_view scene, bool unqualifiedToo) {
  std::vector<params::Preset> presets;
  for (const std::string& name : presetsFor(options, scene, unqualifiedToo)) {
    FoundPreset found = findPreset(scene, name);
    if (!found.preset) throw Error(fmt::format("{}; vitrine --list-params {} lists the scene's own.", found.why, scene));
    presets.push_back(std::move(*found.preset));
  }
  for (params::Preset& preset : presetFilesFor(options, scene)) presets.push_back(std::move(preset));
  return presets;
}

std::vector<params::Preset> presetFilesFor(const Options& options, std::string_view scene) {
  std::vector<params::Preset> presets;
  for (const std::string& file : options.presetFiles) {
    params::PresetRead read = params::readPresetFile(file, findSchema);
    if (!read.preset) throw Error(fmt::format("--preset-file: {}.", read.why));
    if (read.preset->scene == scene) presets.push_back({read.preset->name, {}, std::move(read.preset->values)});
  }
  return presets;
}

void saveRunPreset(const Options& options, const params::Bound& bound) {
  params::PresetStore store = openUserPresets();
  const params::UserPreset preset{options.scene, options.savePreset, params::snapshot(bound, /*includeTransient=*/false)};
  if (std::string why = store.save(preset); !why.empty())
    throw Error(fmt::format("--save-preset {}: {}.", printable(options.savePreset), why));
  std::printf("vitrine: saved preset '%s' of %s in %s\n", preset.name.c_str(), preset.scene.c_str(),
              store.fileOf(preset.scene, preset.name).string().c_str());
}

int runExportPreset(const Options& options) {
  const SceneSetting& wanted = options.exportPreset;
  params::PresetStore store = openUserPresets();
  for (const std::string& warning : store.warnings()) std::fprintf(stderr, "vitrine: presets: %s\n", warning.c_str());
  std::vector<std::string> scenes;
  for (const SceneInfo& info : sceneRegistry())
    if ((wanted.scene.empty() || wanted.scene == info.name) && store.find(info.name, wanted.key))
      scenes.emplace_back(info.name);
  if (scenes.empty())
    throw Error(fmt::format("No preset of yours named '{}'{} in {}.", printable(wanted.key),
                            wanted.scene.empty() ? "" : " for " + wanted.scene, store.folder().string()));
  if (scenes.size() > 1)
    throw Error(fmt::format("Presets named '{}' are kept for {}: say which, as SCENE.NAME.", printable(wanted.key),
                            fmt::join(scenes, " and ")));
  if (std::string why = store.exportTo(scenes.front(), wanted.key, options.out); !why.empty()) throw Error(why);
  std::printf("vitrine: wrote preset '%s' of %s to %s\n", wanted.key.c_str(), scenes.front().c_str(), options.out.c_str());
  return 0;
}

}  // namespace vitrine::host
