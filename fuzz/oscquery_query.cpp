// OSCQuery's HTTP targets and WebSocket commands (src/remote/oscquery.h): any bytes are answered
// with one of the statuses it gives (a namespace node or attribute as JSON that parses, or a refusal),
// and a stream command is LISTEN or IGNORE of a bounded path, or nothing.
#include "remote/oscquery.h"
#include "scenes/catalogue.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string_view>
#include <vector>
#include "support/require.h"

using namespace vitrine;
using namespace vitrine::remote;

using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::vector<const SceneInfo*> scenes = [] {
    std::vector<const SceneInfo*> all;
    for (const SceneInfo& info : sceneRegistry()) all.push_back(&info);
    return all;
  }();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const OscQueryReply reply = answerOscQuery(scenes, OscQueryValues{}, OscQueryHost{}, text);
  require(reply.status == 200 || reply.status == 204 || reply.status == 400 || reply.status == 404, "another status");
  if (reply.status == 200) require(!nlohmann::json::parse(reply.body, nullptr, false).is_discarded(), "200 without JSON");
  if (const auto command = parseStreamCommand(text))
    require(!command->path.empty() && command->path.size() <= kMaxQueryTarget, "an unbounded stream path");
  return 0;
}
