// vitrine --list-params [SCENE]: every parameter of a scene, from its schema alone (no device); and
// --list-keys and --list-presets, the same names one a line, for scripts and the bash completion.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "core/error.h"
#include "host/modes.h"
#include "host/user_presets.h"
#include "params/listing.h"
#include "scenes/catalogue.h"

namespace vitrine::host {

int runListParams(const Options& options) {
  const params::PresetStore mine = openUserPresets();
  for (const std::string& warning : mine.warnings()) std::fprintf(stderr, "vitrine: presets: %s\n", warning.c_str());
  bool first = true;
  for (const auto& info : sceneRegistry()) {
    if (!options.listParams.empty() && info.name != options.listParams) continue;
    std::printf("%s%s", first ? "" : "\n", params::describeSchema(info.name, info.schema()).c_str());
    for (const SceneAction& action : info.actions)  // what --input's "action" verb and remote control trigger
      std::printf("  action %s  %s\n", fmt::format("{} {}", action.name, fmt::join(action.args, " ")).c_str(),
                  std::string(action.help).c_str());
    if (const auto own = mine.presetsOf(info.name); !own.empty()) {  // beside the scene's own, marked
      std::printf("presets of yours (--preset NAME, in %s):\n", mine.folder().string().c_str());
      for (const params::UserPreset* preset : own) {
        std::vector<std::string> pairs;
        for (const auto& [key, value] : preset->values) pairs.push_back(key + "=" + value);
        std::printf("  %s  (yours)  %s\n", preset->name.c_str(), fmt::format("{}", fmt::join(pairs, " ")).c_str());
      }
    }
    first = false;
  }
  if (first) throw Error(unknownScene(options.listParams));
  return 0;
}

int runListKeys(const Options& options) {
  for (const auto& info : sceneRegistry())
    if (options.listParams.empty() || info.name == options.listParams)
      for (const params::Param& param : info.schema().params())
        std::printf("%.*s.%s\n", int(info.name.size()), info.name.data(), param.key.c_str());
  return 0;
}

int runListPresets(const Options& options) {
  const params::PresetStore mine = openUserPresets();  // its warnings are --list-params' to show
  for (const auto& info : sceneRegistry()) {
    if (!options.listParams.empty() && info.name != options.listParams) continue;
    const std::string scene(info.name);
    for (const params::Preset& preset : info.schema().presets()) std::printf("%s.%s\n", scene.c_str(), preset.name.c_str());
    for (const params::UserPreset* preset : mine.presetsOf(scene))
      std::printf("%s.%s\n", scene.c_str(), preset->name.c_str());
  }
  return 0;
}

}  // namespace vitrine::host
