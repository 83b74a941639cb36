// The gallery's settings file (src/params/settings_file.h) with every scene's schema: whatever the
// file holds, loading never throws, and what it loads survives a save and a second load unchanged.
#include "params/settings_file.h"
#include "scenes/catalogue.h"
#include "support/temp_file.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace vitrine;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto path = fuzz::writeTempFile("settings.json", data, size);
  const params::LoadResult loaded = params::loadSettings(path, findSchema);
  const auto copy = fuzz::tempFolder() / "copy" / "settings.json";
  params::saveSettings(copy, loaded.settings, findSchema);
  const params::LoadResult again = params::loadSettings(copy, findSchema);
  if (again.settings.scene != loaded.settings.scene || again.settings.scenes != loaded.settings.scenes ||
      again.settings.unknown != loaded.settings.unknown || !again.warnings.empty()) {
    std::fprintf(stderr, "settings_file: a saved file does not load back to what was saved (%zu warnings%s%s)\n",
                 again.warnings.size(), again.warnings.empty() ? "" : ": ",
                 again.warnings.empty() ? "" : again.warnings[0].c_str());
    std::abort();
  }
  fuzz::clearTempFolder();  // a file that is not settings was renamed aside
  return 0;
}
