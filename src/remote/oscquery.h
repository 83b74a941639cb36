#pragma once
// OSCQuery: the JSON description of the gallery's OSC address space, as OSCQuery clients (ossia score,
// VDMX, Chataigne, TouchDesigner) browse it over HTTP. Made from the scene registry's schemas and the
// values the gallery last published, at each request: nothing is cached, so a scene the registry gains
// is described at once. Pure: no I/O and no state; any target is safe (refused with a status).
//
//   GET /                         the whole namespace: /vitrine/scene, /vitrine/<scene>/<param>, ...
//   GET /vitrine/kifs/step        one node
//   GET /vitrine/kifs/step?VALUE  one attribute: {"VALUE":[9]}
//   GET /?HOST_INFO               the OSC port and transport, and the extensions supported
//
// The paths are those the OSC server accepts, so a client that sends the advertised type to an
// advertised path sets that value.
#include "params/schema.h"

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {
struct SceneInfo;
}

namespace vitrine::remote {

// What the namespace reports as values: the scene showing and every scene's values as remote clients
// see them (params::remoteView), keyed by scene then parameter. A parameter missing here reports its
// default.
struct OscQueryValues {
  std::string scene;
  std::map<std::string, std::map<std::string, std::string, std::less<>>, std::less<>> values;
};

struct OscQueryHost {
  std::string name = "Vitrine";
  std::string oscAddress;  // the bind address; empty for a wildcard bind (the client's own route)
  uint16_t oscPort = 0;    // OSC over UDP on the same port as HTTP and the WebSocket
};

struct OscQueryReply {
  int status = 200;  // 200 with JSON; 204 (the node has no such attribute), 400, 404 with a sentence
  std::string body;
};

inline constexpr size_t kMaxQueryTarget = 512;  // bytes of a request target (path and query) we parse

// The answer to a GET of `target` (path and query; the query may carry token=... among its items,
// which is ignored here). Unknown paths: 404; an unknown or unsupported attribute, several attributes,
// a malformed path or query: 400; an attribute the node lacks (a container's VALUE): 204.
OscQueryReply answerOscQuery(std::span<const SceneInfo* const> scenes, const OscQueryValues& values,
                             const OscQueryHost& host, std::string_view target);

// Whether `path` names a value a client may LISTEN to (a parameter, or /vitrine/scene).
bool listenable(std::span<const SceneInfo* const> scenes, std::string_view path);

// The binary OSC message carrying `path`'s current value, typed as the namespace's TYPE says, as
// LISTEN streams it; nullopt when the path has no value.
std::optional<std::string> oscValueMessage(std::span<const SceneInfo* const> scenes, const OscQueryValues& values,
                                           std::string_view path);

// A client's command over the OSCQuery WebSocket: {"COMMAND":"LISTEN","DATA":"/vitrine/kifs/step"}, or
// IGNORE. Nullopt for anything else (other commands, other shapes, a path longer than kMaxQueryTarget).
struct StreamCommand {
  bool listen = true;  // false: IGNORE
  std::string path;
};
std::optional<StreamCommand> parseStreamCommand(std::string_view text);

// A parameter's OSC type tag as the namespace advertises it: "f", "i", "T" (on/off: send T or F), "s".
char oscType(const params::Param& param);

}  // namespace vitrine::remote
