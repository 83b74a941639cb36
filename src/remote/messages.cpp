#include "remote/messages.h"

#include "params/schema.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace vitrine::remote {
namespace {

using nlohmann::json;

ParseResult fail(std::string why) { return {std::nullopt, std::move(why)}; }
ParseResult succeed(RemoteCommand command) { return {std::move(command), {}}; }

// Nesting deeper than any message needs is refused before the JSON parser sees it: a few kilobytes of
// '[' must not become a deep tree.
bool nestingWithin(std::string_view text, int maxDepth) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (const char c : text) {
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      if (++depth > maxDepth) return false;
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return true;
}

bool plainName(std::string_view name) {
  if (name.empty() || name.size() > kMaxNameLength) return false;
  for (const char c : name)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-'))
      return false;
  return true;
}

// A required string field that is a plain name ("kifs", "step").
std::optional<std::string> nameField(const json& message, const char* field, std::string& error) {
  const auto found = message.find(field);
  if (found == message.end() || !found->is_string()) {
    error = fmt::format("\"{}\" must be a string", field);
    return std::nullopt;
  }
  const auto& name = found->get_ref<const std::string&>();
  if (!plainName(name)) {
    error = fmt::format("\"{}\" must be a name of letters, digits, '_' or '-', at most {} characters", field,
                        kMaxNameLength);
    return std::nullopt;
  }
  return name;
}

std::optional<float> finiteFloat(double value) {
  if (!std::isfinite(value) || std::fabs(value) > double(std::numeric_limits<float>::max())) return std::nullopt;
  return float(value);
}

ParseResult setFromJson(const json& message) {
  std::string error;
  const auto scene = nameField(message, "scene", error);
  if (!scene) return fail(error);
  const auto key = nameField(message, "key", error);
  if (!key) return fail(error);
  const auto value = message.find("value");
  if (value == message.end()) return fail("\"value\" is missing");
  RemoteCommand command{.kind = RemoteCommand::Kind::Set, .scene = *scene, .key = *key};
  if (value->is_string()) {
    command.value = value->get<std::string>();
  } else if (value->is_boolean()) {
    command.value = value->get<bool>() ? "on" : "off";
  } else if (value->is_number()) {
    const auto text = numberText(value->get<double>());
    if (!text) return fail("\"value\" must be a finite number");
    command.value = *text;
  } else {
    return fail("\"value\" must be a string, number or boolean");
  }
  if (command.value.size() > kMaxValueLength)
    return fail(fmt::format("\"value\" is longer than {} characters", kMaxValueLength));
  return succeed(std::move(command));
}

ParseResult actionFromJson(const json& message) {
  std::string error;
  const auto scene = nameField(message, "scene", error);
  if (!scene) return fail(error);
  const auto name = nameField(message, "name", error);
  if (!name) return fail(error);
  RemoteCommand command{.kind = RemoteCommand::Kind::Action, .scene = *scene, .key = *name};
  if (const auto args = message.find("args"); args != message.end()) {
    if (!args->is_array() || args->size() > kMaxActionArgs)
      return fail(fmt::format("\"args\" must be an array of at most {} numbers", kMaxActionArgs));
    for (const json& arg : *args) {
      const auto number = arg.is_number() ? finiteFloat(arg.get<double>()) : std::nullopt;
      if (!number) return fail("\"args\" must hold finite numbers");
      command.args.push_back(*number);
    }
  }
  return succeed(std::move(command));
}

ParseResult pointerFromJson(const json& message) {
  const auto x = message.find("x"), y = message.find("y"), down = message.find("down");
  if (x == message.end() || y == message.end() || !x->is_number() || !y->is_number())
    return fail("\"x\" and \"y\" must be numbers");
  const auto fx = finiteFloat(x->get<double>()), fy = finiteFloat(y->get<double>());
  if (!fx || !fy) return fail("\"x\" and \"y\" must be finite numbers");
  RemoteCommand command{.kind = RemoteCommand::Kind::Pointer, .position = {*fx, *fy}};
  if (down != message.end()) {
    if (!down->is_boolean()) return fail("\"down\" must be true or false");
    command.down = down->get<bool>();
  }
  return succeed(std::move(command));
}

bool presetOp(std::string_view op) { return op == "save" || op == "apply" || op == "delete"; }

// A preset's name is judged by the catalogue (printable, not a built-in's); here only its size.
ParseResult presetCommand(std::string op, std::string scene, std::string name) {
  if (!plainName(scene)) return fail("preset: not a scene name");
  if (name.empty() || name.size() > kMaxNameLength)
    return fail(fmt::format("preset: a name of 1 to {} characters", kMaxNameLength));
  return succeed({.kind = RemoteCommand::Kind::Preset, .scene = std::move(scene), .key = std::move(op), .value = std::move(name)});
}

ParseResult presetFromJson(const json& message) {
  const auto op = message.find("op"), scene = message.find("scene"), name = message.find("name");
  if (op == message.end() || !op->is_string() || !presetOp(op->get_ref<const std::string&>()))
    return fail("\"op\" must be save, apply or delete");
  if (scene == message.end() || !scene->is_string() || name == message.end() || !name->is_string())
    return fail("\"scene\" and \"name\" must be strings");
  return presetCommand(op->get<std::string>(), scene->get<std::string>(), name->get<std::string>());
}

// /vitrine/<a>/<b> split on '/': {"vitrine", a, b}. Empty segments ("//") are malformed.
std::vector<std::string_view> pathSegments(std::string_view path) {
  std::vector<std::string_view> segments;
  if (path.empty() || path.front() != '/') return segments;
  path.remove_prefix(1);
  while (true) {
    const size_t slash = path.find('/');
    segments.push_back(path.substr(0, slash));
    if (slash == std::string_view::npos || segments.size() > 3) break;
    path.remove_prefix(slash + 1);
  }
  return segments;
}

bool isNumeric(const OscArgument& arg) {
  return arg.type == 'i' || arg.type == 'h' || arg.type == 'f' || arg.type == 'd';
}

// A value for /vitrine/<scene>/<param>: numbers as text, T/F as on/off, strings as they are.
std::optional<std::string> oscValueText(const OscArgument& arg) {
  if (arg.type == 'T') return "on";
  if (arg.type == 'F') return "off";
  if (arg.type == 's' || arg.type == 'S') return arg.text;
  if (isNumeric(arg)) return numberText(arg.number);
  return std::nullopt;
}

ParseResult pointerFromOsc(std::span<const OscArgument> args) {
  if (args.size() < 2 || args.size() > 3 || !isNumeric(args[0]) || !isNumeric(args[1]))
    return fail("/vitrine/pointer expects x y [down]: two numbers, then optionally T/F or a number");
  const auto x = finiteFloat(args[0].number), y = finiteFloat(args[1].number);
  if (!x || !y) return fail("/vitrine/pointer: x and y must be finite");
  RemoteCommand command{.kind = RemoteCommand::Kind::Pointer, .position = {*x, *y}};
  if (args.size() == 3) {
    const OscArgument& down = args[2];
    if (down.type == 'T' || down.type == 'F') command.down = down.type == 'T';
    else if (isNumeric(down) && std::isfinite(down.number)) command.down = down.number >= 0.5;
    else return fail("/vitrine/pointer: down must be T/F or a number");
  }
  return succeed(std::move(command));
}

}  // namespace

std::optional<std::string> numberText(double value) {
  const auto single = finiteFloat(value);
  if (!single) return std::nullopt;
  // Whole numbers within int range as integers, so an int parameter reads them.
  if (value == std::trunc(value) && std::fabs(value) <= 2147483647.0) return fmt::format("{}", int64_t(value));
  return params::formatFloat(*single);
}

ParseResult parseSocketMessage(std::string_view text) {
  if (text.size() > kMaxSocketMessage) return fail(fmt::format("longer than {} bytes", kMaxSocketMessage));
  if (!nestingWithin(text, kMaxJsonDepth)) return fail("nested too deeply");
  const json message = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (message.is_discarded()) return fail("not JSON");
  if (!message.is_object()) return fail("not a JSON object");
  const auto type = message.find("type");
  if (type == message.end() || !type->is_string()) return fail("\"type\" must be a string");
  const auto& name = type->get_ref<const std::string&>();
  try {
    if (name == "scene") {
      std::string error;
      const auto scene = nameField(message, "name", error);
      if (!scene) return fail(error);
      return succeed({.kind = RemoteCommand::Kind::Scene, .scene = *scene});
    }
    if (name == "set") return setFromJson(message);
    if (name == "action") return actionFromJson(message);
    if (name == "pointer") return pointerFromJson(message);
    if (name == "preset") return presetFromJson(message);
  } catch (const std::exception& error) {  // a json accessor's type_error: a shape not foreseen above
    return fail(fmt::format("malformed message: {}", error.what()));
  }
  return fail(fmt::format("unknown type '{}'; expected scene, set, action, pointer or preset", name.substr(0, kMaxNameLength)));
}

ParseResult commandFromOsc(std::string_view path, std::span<const OscArgument> args, const Catalogue& catalogue) {
  const auto segments = pathSegments(path);
  if (segments.size() < 2 || segments[0] != "vitrine")
    return fail("unknown address; expected /vitrine/scene, /vitrine/pointer or /vitrine/<scene>/<name>");
  if (segments.size() == 2) {
    if (segments[1] == "scene") {
      if (args.size() != 1 || (args[0].type != 's' && args[0].type != 'S'))
        return fail("/vitrine/scene expects one string, the scene's name");
      if (!plainName(args[0].text)) return fail("/vitrine/scene: not a scene name");
      return succeed({.kind = RemoteCommand::Kind::Scene, .scene = args[0].text});
    }
    if (segments[1] == "pointer") return pointerFromOsc(args);
    return fail("unknown address; expected /vitrine/scene, /vitrine/pointer or /vitrine/<scene>/<name>");
  }
  if (segments.size() != 3 || !plainName(segments[1]) || !plainName(segments[2]))
    return fail("unknown address; expected /vitrine/<scene>/<name>");
  if (segments[1] == "mod") {  // no scene is called "mod": a live source, osc.NAME
    const auto number = args.size() == 1 && isNumeric(args[0]) ? finiteFloat(args[0].number) : std::nullopt;
    if (!number) return fail(fmt::format("/vitrine/mod/{} expects one finite number, 0 to 1", segments[2]));
    return succeed({.kind = RemoteCommand::Kind::Modulation, .key = std::string(segments[2]), .args = {*number}});
  }
  if (segments[1] == "preset") {  // no scene is called "preset" either: the user's presets
    if (!presetOp(segments[2])) return fail("/vitrine/preset/ takes save, apply or delete");
    const auto isText = [](const OscArgument& arg) { return arg.type == 's' || arg.type == 'S'; };
    if (args.size() != 2 || !isText(args[0]) || !isText(args[1]))
      return fail(fmt::format("/vitrine/preset/{} expects two strings: the scene and the preset's name", segments[2]));
    return presetCommand(std::string(segments[2]), args[0].text, args[1].text);
  }
  const std::string scene(segments[1]), name(segments[2]);

  if (catalogue.hasAction(scene, name)) {
    RemoteCommand command{.kind = RemoteCommand::Kind::Action, .scene = scene, .key = name};
    if (args.size() > kMaxActionArgs) return fail(fmt::format("/vitrine/{}/{}: too many arguments", scene, name));
    for (const OscArgument& arg : args) {
      if (arg.type == 'N' || arg.type == 'I') continue;  // nil, impulse: a trigger's press, carrying nothing
      const auto number = isNumeric(arg) ? finiteFloat(arg.number) : std::nullopt;
      if (!number) return fail(fmt::format("/vitrine/{}/{}: arguments must be finite numbers", scene, name));
      command.args.push_back(*number);
    }
    return succeed(std::move(command));
  }

  if (args.size() != 1) return fail(fmt::format("/vitrine/{}/{} expects one value", scene, name));
  const auto value = oscValueText(args[0]);
  if (!value) return fail(fmt::format("/vitrine/{}/{}: the value must be a number, string or T/F", scene, name));
  if (value->size() > kMaxValueLength)
    return fail(fmt::format("/vitrine/{}/{}: the value is longer than {} characters", scene, name, kMaxValueLength));
  return succeed({.kind = RemoteCommand::Kind::Set, .scene = scene, .key = name, .value = *value});
}

}  // namespace vitrine::remote
