// The control page's WebSocket messages (src/remote/messages.h): any bytes either become exactly one
// command or are refused with a reason, and a command's numbers are finite.
#include "remote/messages.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include "support/require.h"

using namespace vitrine::remote;

using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const ParseResult result = parseSocketMessage(std::string_view(reinterpret_cast<const char*>(data), size));
  require(result.command.has_value() == result.error.empty(), "neither a command nor a reason, or both");
  if (!result.command) return 0;
  for (float arg : result.command->args) require(std::isfinite(arg), "a non-finite action argument");
  require(std::isfinite(result.command->position.x) && std::isfinite(result.command->position.y),
          "a non-finite pointer");
  return 0;
}
