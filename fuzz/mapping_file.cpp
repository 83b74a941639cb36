// Mapping files (--map FILE, live/mapping.h) and single lines as the panel and the settings file give
// them. Besides not crashing: a file is taken whole or refused with FILE:LINE and a reason; every
// mapping taken formats to a line that parses back to itself and still fits its scene.
#include "core/error.h"
#include "live/mapping.h"
#include "scenes/catalogue.h"
#include "support/require.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

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
