// The --input script format (src/host/input_script.h): any text either parses or is refused with a
// vitrine::Error naming the line; a parsed script keeps its promises (finite, non-negative times that
// never decrease) and replays to the end through InputPlayer, as a headless run would.
#include "core/error.h"
#include "host/input_script.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include "support/require.h"

using namespace vitrine;

using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  host::InputScript script;
  try {
    script = host::parseInputScript(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.txt");
  } catch (const Error& error) {
    require(std::string_view(error.what()).starts_with("fuzz.txt:"), "an error does not name the line");
    return 0;
  }
  double last = 0.0;
  for (const auto& event : script.events) {
    require(std::isfinite(event.time) && event.time >= last, "times are not finite and non-decreasing");
    last = event.time;
  }
  host::InputPlayer player(script);
  for (const auto& event : script.events) player.step(event.time, {64, 36});  // a step at each event's time
  require(player.finished(), "a step at the last event's time leaves events unapplied");
  return 0;
}
