// vitrine --list-params [SCENE]: every parameter of a scene, from its schema alone (no device).
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdio>

#include "core/error.h"
#include "host/modes.h"
#include "params/listing.h"
#include "scenes/scene.h"

namespace vitrine::host {

int runListParams(const Options& options) {
  bool first = true;
  for (const auto& info : sceneRegistry()) {
    if (!options.listParams.empty() && info.name != options.listParams) continue;
    std::printf("%s%s", first ? "" : "\n", params::describeSchema(info.name, info.schema()).c_str());
    for (const SceneAction& action : info.actions)  // what --input's "action" verb and remote control trigger
      std::printf("  action %s  %s\n", fmt::format("{} {}", action.name, fmt::join(action.args, " ")).c_str(),
                  std::string(action.help).c_str());
    first = false;
  }
  if (first)
    throw Error(fmt::format("Unknown scene '{}'; vitrine --list-scenes shows them.", options.listParams));
  return 0;
}

}  // namespace vitrine::host
