// Mapping files (--map FILE, live/mapping.h) and single lines as the panel and the settings file give
// them. Besides not crashing: a file is taken whole or refused with FILE:LINE and a reason; every
// mapping taken formats to a line that parses back to itself and still fits its scene.
#include "core/error.h"
#include "live/mapping.h"
#include "scenes/scene.h"
#include "scenes/schemas.h"
#include "support/require.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {

// The fuzz build links no scenes' GPU code: the registry a mapping is checked against is the scenes'
// schemas with neon's "release" as their one action (the registry's lookups, scenes/registry.cpp, run as they are).
std::span<const SceneInfo> sceneRegistry() {
  static constexpr std::string_view kReleaseArgs[] = {"x", "y", "z"};
  static constexpr SceneAction kRelease[] = {{"release", kReleaseArgs, ""}};
  static const std::vector<SceneInfo> table = [] {
    std::vector<SceneInfo> scenes;
    for (const SceneSchema& scene : sceneSchemas())
      scenes.push_back({scene.name, scene.name, 0, nullptr, scene.schema, "",
                        scene.name == "neon" ? std::span<const SceneAction>(kRelease) : std::span<const SceneAction>()});
    return scenes;
  }();
  return table;
}

}  // namespace vitrine

using namespace vitrine;
using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (const live::Mapping& mapping : live::parseMappingText(text, "fuzz.map")) {
      const std::string line = live::formatMapping(mapping);
      std::string why;
      const auto again = live::parseMapping(line, &why);
      require(again && *again == mapping, "a mapping's line does not parse back to itself");
      require(live::checkMapping(*again, *findScene(mapping.scene)).empty(), "a mapping taken no longer fits its scene");
    }
  } catch (const Error& error) {
    require(std::string_view(error.what()).starts_with("fuzz.map:"), "a refusal does not name FILE:LINE");
  }
  std::string why;
  if (const auto mapping = live::parseMapping(text, &why)) {
    require(live::parseMapping(live::formatMapping(*mapping), nullptr) == mapping, "a line does not round-trip");
  } else {
    require(!why.empty(), "a refused line gives no reason");
  }
  return 0;
}
