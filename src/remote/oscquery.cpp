#include "remote/oscquery.h"

#include "scenes/catalogue.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <cstring>

namespace vitrine::remote {
namespace {

using nlohmann::json;

constexpr int kReadWrite = 3, kWriteOnly = 2, kNoValue = 0;

// Attributes this namespace fills, and those OSCQuery defines that it leaves out (asked for: 400).
constexpr std::string_view kNodeAttributes[] = {"FULL_PATH", "CONTENTS", "TYPE", "ACCESS", "VALUE", "RANGE",
                                                "DESCRIPTION", "TAGS"};

std::string dump(const json& value) { return value.dump(-1, ' ', false, json::error_handler_t::replace); }

OscQueryReply refuse(int status, std::string why) { return {status, std::move(why) + "\n"}; }

const params::Param* paramOf(const SceneInfo& scene, std::string_view key) { return scene.schema().find(key); }

// The text a parameter reports: the value last published, else its default as clients see it.
std::string currentText(const OscQueryValues& values, const SceneInfo& scene, const params::Param& param) {
  if (const auto sceneIt = values.values.find(scene.name); sceneIt != values.values.end())
    if (const auto it = sceneIt->second.find(param.key); it != sceneIt->second.end()) return it->second;
  return params::remoteView(param, param.defaultText);
}

// A value in JSON as its OSC type carries it.
json jsonValue(const params::Param& param, const std::string& text) {
  switch (oscType(param)) {
    case 'f': return std::strtod(text.c_str(), nullptr);
    case 'i': return std::strtoll(text.c_str(), nullptr, 10);
    case 'T': return text == "on";
    default: return text;
  }
}

json paramNode(const std::string& path, const SceneInfo& scene, const params::Param& param,
               const OscQueryValues& values) {
  json node = {{"FULL_PATH", path},
               {"TYPE", std::string(1, oscType(param))},
               {"ACCESS", kReadWrite},
               {"VALUE", json::array({jsonValue(param, currentText(values, scene, param))})},
               {"DESCRIPTION", param.help.empty() ? param.label : param.help}};
  if (!param.group.empty()) node["TAGS"] = json::array({param.group});
  if (param.has(params::kNamesFile)) {
    node["RANGE"] = json::array({{{"VALS", param.builtIns}}});  // a client may name no file
  } else if (param.kind == params::Kind::Float) {
    node["RANGE"] = json::array({{{"MIN", param.min}, {"MAX", param.max}}});
  } else if (param.kind == params::Kind::Int) {
    node["RANGE"] = json::array({{{"MIN", int64_t(param.min)}, {"MAX", int64_t(param.max)}}});
  } else if (param.kind == params::Kind::Choice) {
    node["RANGE"] = json::array({{{"VALS", param.choices}}});
  }
  return node;
}

json actionNode(const std::string& path, const SceneAction& action) {
  json node = {{"FULL_PATH", path}, {"ACCESS", kWriteOnly}};
  std::string description(action.help);
  if (action.args.empty()) {
    node["TYPE"] = "N";  // a trigger: sent with no argument (or a nil, as a button sends it)
  } else {
    node["TYPE"] = std::string(action.args.size(), 'f');
    std::vector<std::string> names(action.args.begin(), action.args.end());
    description = fmt::format("{}: {}", fmt::join(names, " "), description);  // "x y z: a tube head ..."
  }
  node["DESCRIPTION"] = description;
  return node;
}

json method(const std::string& path, std::string type, int access, std::string description) {
  return {{"FULL_PATH", path}, {"TYPE", std::move(type)}, {"ACCESS", access}, {"DESCRIPTION", std::move(description)}};
}

json container(const std::string& path, std::string description, json contents) {
  return {{"FULL_PATH", path}, {"ACCESS", kNoValue}, {"DESCRIPTION", std::move(description)},
          {"CONTENTS", std::move(contents)}};
}

json sceneNode(const SceneInfo& scene, const OscQueryValues& values) {
  const std::string base = fmt::format("/vitrine/{}", scene.name);
  json contents = json::object();
  for (const params::Param& param : scene.schema().params())
    contents[param.key] = paramNode(base + "/" + param.key, scene, param, values);
  for (const SceneAction& action : scene.actions) {
    const std::string name(action.name);
    contents[name] = actionNode(base + "/" + name, action);
  }
  return container(base, std::string(scene.title), std::move(contents));
}

json namespaceTree(std::span<const SceneInfo* const> scenes, const OscQueryValues& values) {
  std::vector<std::string> names;
  for (const SceneInfo* scene : scenes) names.emplace_back(scene->name);
  json sceneSwitch = method("/vitrine/scene", "s", kReadWrite, "the scene showing: send a scene's name to switch");
  sceneSwitch["VALUE"] = json::array({values.scene});
  sceneSwitch["RANGE"] = json::array({{{"VALS", names}}});
  json pointer = method("/vitrine/pointer", "fff", kWriteOnly,
                        "the cursor: x and y from 0 to 1 from the top left, then down (0 or 1)");
  pointer["RANGE"] = json::array({{{"MIN", 0}, {"MAX", 1}}, {{"MIN", 0}, {"MAX", 1}}, {{"MIN", 0}, {"MAX", 1}}});
  json presets = container("/vitrine/preset", "the user's presets: the scene, then the preset's name",
                           {{"save", method("/vitrine/preset/save", "ss", kWriteOnly,
                                            "save the values of the scene showing as a preset")},
                            {"apply", method("/vitrine/preset/apply", "ss", kWriteOnly,
                                             "apply a preset, the scene's own or the user's")},
                            {"delete", method("/vitrine/preset/delete", "ss", kWriteOnly, "delete a preset of the user's")}});
  json contents = {{"scene", std::move(sceneSwitch)},
                   {"pointer", std::move(pointer)},
                   {"preset", std::move(presets)},
                   {"token", method("/vitrine/token", "s", kWriteOnly,
                                    "the page's access token: trusts the sender's address for the run")}};
  for (const SceneInfo* scene : scenes) contents[std::string(scene->name)] = sceneNode(*scene, values);
  return container("/", "", {{"vitrine", container("/vitrine", "Vitrine, a gallery of real-time pieces", std::move(contents))}});
}

json hostInfo(const OscQueryHost& host) {
  json extensions = {{"ACCESS", true},       {"VALUE", true},         {"RANGE", true},         {"DESCRIPTION", true},
                     {"TAGS", true},         {"LISTEN", true},        {"CLIPMODE", false},     {"UNIT", false},
                     {"CRITICAL", false},    {"EXTENDED_TYPE", false}, {"OVERLOADS", false},   {"HTML", false},
                     {"PATH_CHANGED", false}, {"PATH_ADDED", false},  {"PATH_REMOVED", false}, {"PATH_RENAMED", false}};
  json info = {{"NAME", host.name}, {"OSC_PORT", host.oscPort}, {"OSC_TRANSPORT", "UDP"}, {"EXTENSIONS", std::move(extensions)}};
  if (!host.oscAddress.empty()) info["OSC_IP"] = host.oscAddress;
  return info;
}

bool pathCharacter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '/' || c == '.';
}

// The node at `path` ("/", "/vitrine", "/vitrine/kifs/step") inside `tree`, or null.
const json* findNode(const json& tree, std::string_view path) {
  const json* node = &tree;
  path.remove_prefix(1);
  while (!path.empty()) {
    const size_t slash = path.find('/');
    const std::string name(path.substr(0, slash));
    const auto contents = node->find("CONTENTS");
    if (contents == node->end()) return nullptr;
    const auto child = contents->find(name);
    if (child == contents->end()) return nullptr;
    node = &*child;
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
  }
  return node;
}

// The parameter at /vitrine/<scene>/<key>, or nulls.
std::pair<const SceneInfo*, const params::Param*> paramAt(std::span<const SceneInfo* const> scenes,
                                                          std::string_view path) {
  constexpr std::string_view prefix = "/vitrine/";
  if (!path.starts_with(prefix)) return {};
  path.remove_prefix(prefix.size());
  const size_t slash = path.find('/');
  if (slash == std::string_view::npos) return {};
  const std::string_view sceneName = path.substr(0, slash), key = path.substr(slash + 1);
  for (const SceneInfo* scene : scenes)
    if (scene->name == sceneName) return {scene, paramOf(*scene, key)};
  return {};
}

void putPadded(std::string& out, std::string_view text) {
  out.append(text);
  out.append(4 - text.size() % 4, '\0');  // at least one terminating NUL, then to a multiple of 4
}

void putBigEndian(std::string& out, uint32_t bits) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(char((bits >> shift) & 0xFF));
}

}  // namespace

char oscType(const params::Param& param) {
  if (param.has(params::kNamesFile)) return 's';
  switch (param.kind) {
    case params::Kind::Float: return 'f';
    case params::Kind::Int: return 'i';
    case params::Kind::Bool: return 'T';
    case params::Kind::Choice:
    case params::Kind::Colour:
    case params::Kind::Custom: return 's';
  }
  return 's';
}

OscQueryReply answerOscQuery(std::span<const SceneInfo* const> scenes, const OscQueryValues& values,
                             const OscQueryHost& host, std::string_view target) {
  if (target.size() > kMaxQueryTarget) return refuse(400, fmt::format("The request is longer than {} bytes", kMaxQueryTarget));
  const size_t question = target.find('?');
  std::string_view path = target.substr(0, question);
  const std::string_view query = question == std::string_view::npos ? std::string_view() : target.substr(question + 1);
  if (path.empty() || path.front() != '/' || !std::all_of(path.begin(), path.end(), pathCharacter) ||
      path.find("//") != std::string_view::npos)
    return refuse(400, "Not an OSC address: letters, digits, '_', '-', '.' between single slashes");
  if (path.size() > 1 && path.back() == '/') path.remove_suffix(1);

  // The query's items: token=... (the server's), and at most one attribute name.
  std::string_view attribute;
  for (std::string_view rest = query; !rest.empty();) {
    const size_t amp = rest.find('&');
    const std::string_view item = rest.substr(0, amp);
    rest = amp == std::string_view::npos ? std::string_view() : rest.substr(amp + 1);
    if (item.empty() || item.starts_with("token=")) continue;
    if (!attribute.empty()) return refuse(400, "Ask for one attribute at a time");
    if (item.find('=') != std::string_view::npos || item.size() > 32)
      return refuse(400, "The query names an attribute (?VALUE) and nothing else");
    attribute = item;
  }

  if (attribute == "HOST_INFO") return {200, dump(hostInfo(host))};
  const json tree = namespaceTree(scenes, values);
  const json* node = findNode(tree, path);
  if (!node) return refuse(404, "No such OSC address");
  if (attribute.empty()) return {200, dump(*node)};
  if (std::find(std::begin(kNodeAttributes), std::end(kNodeAttributes), attribute) == std::end(kNodeAttributes))
    return refuse(400, fmt::format("Attribute {} is not supported here; see ?HOST_INFO", attribute.substr(0, 32)));
  const std::string name(attribute);
  const auto found = node->find(name);
  if (found == node->end()) return {204, {}};
  return {200, dump(json{{name, *found}})};
}

std::optional<StreamCommand> parseStreamCommand(std::string_view text) {
  if (text.size() > 4 * kMaxQueryTarget) return std::nullopt;
  const json message = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!message.is_object()) return std::nullopt;  // a parse failure is discarded, which is no object
  const auto command = message.find("COMMAND"), data = message.find("DATA");
  if (command == message.end() || data == message.end() || !command->is_string() || !data->is_string())
    return std::nullopt;
  const auto& name = command->get_ref<const std::string&>();
  const auto& path = data->get_ref<const std::string&>();
  if ((name != "LISTEN" && name != "IGNORE") || path.empty() || path.size() > kMaxQueryTarget) return std::nullopt;
  return StreamCommand{name == "LISTEN", path};
}

bool listenable(std::span<const SceneInfo* const> scenes, std::string_view path) {
  return path == "/vitrine/scene" || paramAt(scenes, path).second != nullptr;
}

std::optional<std::string> oscValueMessage(std::span<const SceneInfo* const> scenes, const OscQueryValues& values,
                                           std::string_view path) {
  std::string message;
  putPadded(message, path);
  if (path == "/vitrine/scene") {
    putPadded(message, ",s");
    putPadded(message, values.scene);
    return message;
  }
  const auto [scene, param] = paramAt(scenes, path);
  if (!param) return std::nullopt;
  const std::string text = currentText(values, *scene, *param);
  switch (oscType(*param)) {
    case 'f':
      putPadded(message, ",f");
      putBigEndian(message, std::bit_cast<uint32_t>(std::strtof(text.c_str(), nullptr)));
      break;
    case 'i':
      putPadded(message, ",i");
      putBigEndian(message, uint32_t(int32_t(std::strtol(text.c_str(), nullptr, 10))));
      break;
    case 'T': putPadded(message, text == "on" ? ",T" : ",F"); break;
    default:
      putPadded(message, ",s");
      putPadded(message, text);
  }
  return message;
}

}  // namespace vitrine::remote
