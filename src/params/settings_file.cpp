#include "params/settings_file.h"

#include "core/atomic_file.h"
#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <cstdlib>
#include <ctime>
#include <fstream>

namespace vitrine::params {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keeps the file's order (and ours: version first) for a reader

namespace {

// A settings file is three levels deep; a limit far above that keeps a hostile file from building a
// structure that later recursion (dump, destruction) could overflow the stack on.
constexpr int kMaxDepth = 32;

Json parseLimited(const std::string& text) {
  const auto limitDepth = [](int depth, Json::parse_event_t event, Json&) {
    if ((event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) && depth >= kMaxDepth)
      throw FileRefused{fmt::format("nested deeper than {} levels", kMaxDepth)};
    return true;
  };
  try {
    return Json::parse(text, limitDepth);
  } catch (const Json::parse_error& e) {
    // Not e.what(): it quotes the bytes it stopped at, and those may be binary.
    throw FileRefused{e.byte > text.size() ? "not JSON: it ends too early" : fmt::format("not JSON at byte {}", e.byte)};
  } catch (const Json::out_of_range&) {  // a number no double holds (1e400), anywhere in the file
    throw FileRefused{"a number out of range"};
  } catch (const Json::exception& e) {  // any other refusal of the parser is the same: not settings
    throw FileRefused{fmt::format("not JSON (error {})", e.id)};
  }
}

}  // namespace

// "settings.json" → "settings.json.bad-20250101-120000" (then "-2", "-3" if taken): the user's file is
// kept for a look, out of the way of the next save.
std::string moveAside(const fs::path& path) {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  const std::string base = path.string() + ".bad-" + stamp;
  fs::path target = base;
  std::error_code ec;
  for (int n = 2; fs::exists(fs::symlink_status(target, ec)); ++n) target = fmt::format("{}-{}", base, n);
  fs::rename(path, target, ec);
  if (ec) return fmt::format("could not be moved aside ({})", ec.message());
  return fmt::format("moved it to {}", target.string());
}

namespace {

std::string_view expected(Kind kind) {
  switch (kind) {
    case Kind::Float: return "a number";
    case Kind::Int: return "a whole number";
    case Kind::Bool: return "true or false";
    case Kind::Choice:
    case Kind::Colour:
    case Kind::Custom: return "a string";
  }
  return "?";
}

// The text a JSON value stands for, when its JSON type fits the kind; the parameter's parse then
// judges the text exactly as it judges "--set key=text".
bool textOf(const Json& value, Kind kind, std::string& text, std::string& why) {
  const bool fits = (kind == Kind::Float || kind == Kind::Int) ? value.is_number()
                    : kind == Kind::Bool                        ? value.is_boolean()
                                                                : value.is_string();
  if (!fits) {
    why = fmt::format("expected {}, found {}", expected(kind), value.type_name());
    return false;
  }
  // dump() of a number is its shortest round-trip text ("0.05", "1e+308", "9.0"): a float parse
  // refuses what overflows a float, an int parse what is not whole.
  text = value.is_boolean() ? (value.get<bool>() ? "on" : "off") : value.is_string() ? value.get<std::string>() : value.dump();
  return true;
}

// A value as a warning quotes it: its JSON, cut short (a hostile file may hold a megabyte string).
std::string shortText(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

}  // namespace

// The typed JSON for a canonical text; text that does not read as its kind stays a string (nothing lost).
Json typedValue(const Param* param, const std::string& text) {
  if (!param) return text;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  if (param->kind == Kind::Float) {
    double value = 0.0;
    if (const auto [end, ec] = std::from_chars(first, last, value); ec == std::errc() && end == last) return value;
  } else if (param->kind == Kind::Int) {
    int64_t value = 0;
    if (const auto [end, ec] = std::from_chars(first, last, value); ec == std::errc() && end == last) return value;
  } else if (param->kind == Kind::Bool) {
    bool value = false;
    if (parseBoolText(text, value, nullptr)) return value;
  }
  return text;
}

std::vector<ValueProblem> checkSceneValues(const Json& values, const Schema& schema, KeyValues& kept, Json& unknown) {
  std::vector<ValueProblem> problems;
  const auto scratch = schema.makeDefaults();  // each parse writes only its own field
  for (const auto& [key, value] : values.items()) {
    const Param* param = schema.find(key);
    if (!param) {  // from another version: the caller decides whether it is kept
      unknown[key] = value;
      continue;
    }
    std::string text, why;
    if (param->has(kTransient))
      why = "not kept between runs";
    else if (textOf(value, param->kind, text, why) && param->parse(scratch.get(), text, &why))
      kept.emplace_back(key, param->format(scratch.get()));  // canonical: "1" for 1, "0.05" for 0.05000001
    if (!why.empty()) problems.push_back({key, shortText(value), why});
  }
  return problems;
}

namespace {

void loadScene(const std::string& where, const std::string& name, const Json& values, const Schema& schema,
               LoadResult& result) {
  if (!values.is_object()) {
    result.warnings.push_back(fmt::format("{}: scenes.{} is {}, not an object; using its defaults", where, printable(name), values.type_name()));
    return;
  }
  Json unknown = Json::object();
  for (const ValueProblem& problem : checkSceneValues(values, schema, result.settings.scenes[name], unknown))
    result.warnings.push_back(fmt::format("{}: {}.{}={}: {}; using the default", where, printable(name),
                                              printable(problem.key), printable(problem.value), printable(problem.why)));
  for (const auto& [key, value] : unknown.items()) result.settings.unknown["scenes"][name][key] = value;
}

}  // namespace

fs::path defaultSettingsPath() {
  const char* config = std::getenv("XDG_CONFIG_HOME");
  if (config && *config && fs::path(config).is_absolute()) return fs::path(config) / "vitrine" / "settings.json";
  const char* home = std::getenv("HOME");
  if (home && *home) return fs::path(home) / ".config" / "vitrine" / "settings.json";
  return {};
}

Json readJsonFile(const fs::path& path, uintmax_t maxBytes) {
  return parseLimited(readBoundedFile(path, maxBytes));
}

namespace {

// What happens to a file that is not settings, as the end of the warning that says so.
std::string whatBecomesOf(const fs::path& path, LoadMode mode) {
  switch (mode) {
    case LoadMode::MoveBadAside: return moveAside(path) + "; starting from the defaults";
    case LoadMode::ReplaceBad: return moveAside(path) + "; writing this gallery's values in its place";
    case LoadMode::LeaveAlone: break;
  }
  return "left as it is";
}

LoadResult loadChecked(const fs::path& path, const SchemaLookup& schemaFor, LoadMode mode) {
  LoadResult result;
  const std::string where = path.string();
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) return result;  // first start
  if (ec) {
    result.warnings.push_back(fmt::format("{}: cannot read it ({}); starting from the defaults", where, ec.message()));
    return result;
  }
  // A directory or a device in its place is not ours to move: say so and leave it.
  if (!fs::is_regular_file(status)) {
    result.warnings.push_back(fmt::format("{}: not a regular file; starting from the defaults", where));
    return result;
  }

  Json root;
  try {
    root = readJsonFile(path, kMaxSettingsBytes);
    if (!root.is_object()) throw FileRefused{fmt::format("{} at the top, not an object", root.type_name())};
    if (root.contains("version") && root["version"] != kSettingsVersion)
      throw FileRefused{fmt::format("version {}, this build reads version {}", root["version"].dump(), kSettingsVersion)};
  } catch (const FileRefused& bad) {
    result.readable = false;
    const std::string fallback = whatBecomesOf(path, mode);
    result.warnings.push_back(fmt::format("{} is not a settings file ({}); {}", where, bad.why, fallback));
    return result;
  }

  Settings& settings = result.settings;
  for (const auto& [key, value] : root.items()) {
    if (key == "version") continue;
    if (key == "scene") {
      if (!value.is_string())
        result.warnings.push_back(fmt::format("{}: scene: expected a string, found {}; using the default", where, value.type_name()));
      else if (!schemaFor || !schemaFor(value.get<std::string>()))
        result.warnings.push_back(fmt::format("{}: scene: no scene '{}'; using the default", where, printable(value.get<std::string>())));
      else
        settings.scene = value.get<std::string>();
    } else if (key == "scenes") {
      if (!value.is_object()) {
        result.warnings.push_back(fmt::format("{}: scenes: expected an object, found {}; using the defaults", where, value.type_name()));
        continue;
      }
      for (const auto& [name, values] : value.items()) {
        if (const Schema* schema = schemaFor ? schemaFor(name) : nullptr)
          loadScene(where, name, values, *schema, result);
        else
          settings.unknown["scenes"][name] = values;  // a scene of another version: kept as it is
      }
    } else if (key == "mappings" && value.is_object()) {
      for (const auto& [name, lines] : value.items()) {
        if (!schemaFor || !schemaFor(name) || !lines.is_array()) {
          settings.unknown["mappings"][name] = lines;  // another version's scene, or not ours to judge
          continue;
        }
        for (const auto& line : lines) {
          if (line.is_string()) settings.mappings[name].push_back(line.get<std::string>());
          else result.warnings.push_back(fmt::format("{}: mappings.{}: expected lines of text, found {}; dropped", where, printable(name), line.type_name()));
        }
      }
    } else if (key == "live" && value.is_object()) {
      for (const auto& [name, item] : value.items()) {
        if (name == "audio_input" && item.is_boolean()) settings.audioInput = item.get<bool>();
        else if (name == "audio_device" && item.is_string()) settings.audioDevice = item.get<std::string>();
        else settings.unknown["live"][name] = item;
      }
    } else if (key == "outputs" && value.is_object()) {
      for (const auto& [name, warp] : value.items()) {
        if (warp.is_object()) settings.outputs[name] = warp;
        else result.warnings.push_back(fmt::format("{}: outputs.{}: expected an object, found {}; dropped", where, printable(name), warp.type_name()));
      }
    } else if (key == "filters" && value.is_object()) {
      for (const auto& [name, chain] : value.items()) {
        if (chain.is_array()) settings.filters[name] = chain;
        else result.warnings.push_back(fmt::format("{}: filters.{}: expected an array, found {}; dropped", where, printable(name), chain.type_name()));
      }
    } else if (key == "transition" && value.is_object()) {
      settings.transition = value;
    } else {
      settings.unknown[key] = value;
    }
  }
  return result;
}

}  // namespace

LoadResult loadSettings(const fs::path& path, const SchemaLookup& schemaFor, LoadMode mode) {
  try {
    return loadChecked(path, schemaFor, mode);
  } catch (const std::exception& e) {
    // Whatever else goes wrong reading it (memory, a library's surprise) ends like a file that does
    // not parse: the gallery, and above all the kiosk, must never be stopped by its own saved state.
    LoadResult result;
    result.readable = false;
    const std::string fallback = whatBecomesOf(path, mode);
    result.warnings.push_back(fmt::format("{} could not be read ({}); {}", path.string(), e.what(), fallback));
    return result;
  }
}

Json valuesJson(const Bound& bound, bool includeTransient) {
  Json out = Json::object();
  for (const auto& [key, text] : snapshot(bound, includeTransient)) out[key] = typedValue(bound.schema->find(key), text);
  return out;
}

void saveSettings(const fs::path& path, const Settings& settings, const SchemaLookup& schemaFor) {
  // Version and scene first, for a reader; then what was not understood, in its place; then our values,
  // which win where both name the same key.
  Json out = Json::object();
  out["version"] = kSettingsVersion;
  if (!settings.scene.empty()) out["scene"] = settings.scene;
  if (settings.unknown.is_object())
    for (const auto& [key, value] : settings.unknown.items())
      if (key != "version" && key != "scene") out[key] = Json(value);
  Json& scenes = out["scenes"];
  if (!scenes.is_object()) scenes = Json::object();
  for (const auto& [name, values] : settings.scenes) {
    Json& scene = scenes[name];
    if (!scene.is_object()) scene = Json::object();
    const Schema* schema = schemaFor ? schemaFor(name) : nullptr;
    for (const auto& [key, text] : values) {
      const Param* param = schema ? schema->find(key) : nullptr;
      if (param && param->has(kTransient)) continue;
      scene[key] = typedValue(param, text);
    }
  }
  if (!settings.mappings.empty()) {
    Json& mappings = out["mappings"];
    if (!mappings.is_object()) mappings = Json::object();
    for (const auto& [name, lines] : settings.mappings) mappings[name] = lines;
  }
  if (settings.audioInput || !settings.audioDevice.empty()) {
    Json& live = out["live"];
    if (!live.is_object()) live = Json::object();
    live["audio_input"] = settings.audioInput;
    if (!settings.audioDevice.empty()) live["audio_device"] = settings.audioDevice;
  }
  if (!settings.outputs.empty()) {
    Json& outputs = out["outputs"];
    if (!outputs.is_object()) outputs = Json::object();
    for (const auto& [name, warp] : settings.outputs) outputs[name] = warp;
  }
  if (!settings.filters.empty()) {
    Json& filters = out["filters"];
    if (!filters.is_object()) filters = Json::object();
    for (const auto& [name, chain] : settings.filters) filters[name] = chain;
  }
  if (settings.transition.is_object()) out["transition"] = settings.transition;

  writeJsonFile(path, out);
}

void writeJsonFile(const fs::path& path, const Json& out) {
  if (const fs::path folder = path.parent_path(); !folder.empty()) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw Error(fmt::format("Cannot create {}: {}", folder.string(), ec.message()));
  }
  // replace: a key from a hand-edited file with bad UTF-8 must not make the save throw.
  const std::string text = out.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
  replaceAtomically(resolveLinks(path), [&](const fs::path& temporary) {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(text.data(), std::streamsize(text.size()));
    file.close();
    if (!file) throw Error(fmt::format("Cannot write {}", temporary.string()));
  });
}

fs::path resolveLinks(const fs::path& path) {
  constexpr int kMaxLinks = 40;  // the kernel's own limit (ELOOP) for following links
  fs::path resolved = path;
  for (int hops = 0; hops <= kMaxLinks; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(resolved, ec))) return resolved;
    const fs::path target = fs::read_symlink(resolved, ec);
    if (ec) throw Error(fmt::format("Cannot follow the link {}: {}", resolved.string(), ec.message()));
    resolved = target.is_absolute() ? target : resolved.parent_path() / target;
  }
  throw Error(fmt::format("Cannot write {}: more than {} symbolic links in a row (a loop?)", path.string(), kMaxLinks));
}

Settings mergeSettings(Settings disk, const Settings& ours, const SettingsChanges& changed) {
  if (changed.all) return ours;
  if (changed.scene) disk.scene = ours.scene;
  for (const auto& [scene, keys] : changed.keys) {
    const auto mine = ours.scenes.find(scene);
    KeyValues& theirs = disk.scenes[scene];
    for (const std::string& key : keys) {
      const auto has = [&](const auto& kv) { return kv.first == key; };
      const auto there = std::find_if(theirs.begin(), theirs.end(), has);
      const auto it = mine == ours.scenes.end() ? KeyValues::const_iterator{}
                                                : std::find_if(mine->second.begin(), mine->second.end(), has);
      if (mine == ours.scenes.end() || it == mine->second.end()) {
        if (there != theirs.end()) theirs.erase(there);  // changed here to no value: gone
      } else if (there != theirs.end()) {
        there->second = it->second;  // in its place, for a reader of the file
      } else {
        theirs.push_back(*it);
      }
    }
    if (theirs.empty() && mine == ours.scenes.end()) disk.scenes.erase(scene);
  }
  for (const std::string& scene : changed.mappings) {
    const auto mine = ours.mappings.find(scene);
    if (mine == ours.mappings.end() || mine->second.empty()) disk.mappings.erase(scene);
    else disk.mappings[scene] = mine->second;
  }
  if (changed.live) disk.audioInput = ours.audioInput, disk.audioDevice = ours.audioDevice;
  for (const std::string& output : changed.outputs) {
    const auto mine = ours.outputs.find(output);
    if (mine == ours.outputs.end()) disk.outputs.erase(output);
    else disk.outputs[output] = mine->second;
  }
  for (const std::string& scene : changed.filters) {
    const auto mine = ours.filters.find(scene);
    if (mine == ours.filters.end()) disk.filters.erase(scene);
    else disk.filters[scene] = mine->second;
  }
  if (changed.transition) disk.transition = ours.transition;
  return disk;
}

FittedValues applyWhatFits(const KeyValues& values, const std::function<std::string(const KeyValues&)>& apply) {
  FittedValues fitted;
  fitted.why = values.empty() ? std::string() : apply(values);
  if (fitted.why.empty()) {
    fitted.kept = values;
    return fitted;
  }
  const auto text = [](const auto& kv) { return kv.first + "=" + kv.second; };
  for (size_t skip = values.size(); skip-- > 0;) {
    KeyValues others = values;
    others.erase(others.begin() + std::ptrdiff_t(skip));
    if (apply(others).empty()) {
      fitted.kept = std::move(others);
      fitted.dropped.push_back(text(values[skip]));
      return fitted;
    }
  }
  for (const auto& kv : values) {
    KeyValues candidate = fitted.kept;
    candidate.push_back(kv);
    if (apply(candidate).empty())
      fitted.kept = std::move(candidate);
    else
      fitted.dropped.push_back(text(kv));
  }
  return fitted;
}

void SettingsSaver::markDirty(Clock::time_point now) {
  dirty_ = true;
  lastChange_ = now;
}

bool SettingsSaver::due(Clock::time_point now) {
  if (!dirty_ || now - lastChange_ < delay_) return false;
  dirty_ = false;
  return true;
}

bool SettingsSaver::flush() {
  const bool was = dirty_;
  dirty_ = false;
  return was;
}

}  // namespace vitrine::params
