// vitrine --list-params [SCENE]. For now each scene's parameterNames(), read from an instance of the
// scene made on the chosen device: a stand-in until the parameter schema (src/params/schema.h) can
// list keys, types, ranges and help without a device. Replace this file, not its callers.
#include <fmt/format.h>

#include <cstdio>
#include <vector>

#include "core/error.h"
#include "gpu/device.h"
#include "gpu/program.h"
#include "host/modes.h"
#include "scenes/scene.h"

namespace vitrine::host {

int runListParams(const Options& options) {
  std::vector<const SceneInfo*> scenes;
  if (options.listParams.empty()) {
    for (const auto& info : sceneRegistry()) scenes.push_back(&info);
  } else if (const SceneInfo* info = findScene(options.listParams)) {
    scenes.push_back(info);
  } else {
    throw Error(fmt::format("Unknown scene '{}'; vitrine --list-scenes shows them.", options.listParams));
  }
  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device});
  gpu::ProgramLibrary programs(device);
  for (const SceneInfo* info : scenes) {
    const auto scene = info->create(SceneContext{device, programs, 1});
    std::printf("%.*s\n", int(info->name.size()), info->name.data());
    for (const auto& name : scene->parameterNames()) std::printf("  %s\n", name.c_str());
  }
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

}  // namespace vitrine::host
