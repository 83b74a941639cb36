#include "params/preset_store.h"

#include "core/error.h"
#include "core/printable.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace vitrine::params {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

Json valuesObject(const Schema* schema, const KeyValues& values) {
  Json out = Json::object();
  for (const auto& [key, text] : values) out[key] = typedValue(schema ? schema->find(key) : nullptr, text);
  return out;
}

// The values of a preset file checked as the settings file checks a scene's: canonical text, or why
// the preset cannot be one ("step=12: above the maximum 9"). All or nothing, unlike settings.
std::string checkedValues(const Json& values, const Schema& schema, KeyValues& kept) {
  if (!values.is_object()) return fmt::format("values is {}, not an object", values.type_name());
  Json unknown = Json::object();
  const std::vector<ValueProblem> problems = checkSceneValues(values, schema, kept, unknown);
  if (!problems.empty())
    return fmt::format("{}={}: {}", printable(problems.front().key), problems.front().value, problems.front().why);
  if (!unknown.empty()) return fmt::format("{}: no such parameter", printable(unknown.items().begin().key()));
  return {};
}

UserPreset presetOf(const Json& root, const SchemaLookup& schemaFor) {
  if (!root.is_object()) throw FileRefused{fmt::format("{} at the top, not an object", root.type_name())};
  if (root.value("version", Json(kPresetVersion)) != kPresetVersion)
    throw FileRefused{fmt::format("version {}, this build reads version {}", root["version"].dump(), kPresetVersion)};
  for (const char* field : {"scene", "name"})
    if (!root.contains(field) || !root[field].is_string()) throw FileRefused{fmt::format("no \"{}\" string", field)};
  UserPreset preset{root["scene"].get<std::string>(), root["name"].get<std::string>(), {}};
  const Schema* schema = schemaFor ? schemaFor(preset.scene) : nullptr;
  if (!schema) throw FileRefused{fmt::format("no scene '{}' in this build", printable(preset.scene))};
  if (std::string why = presetNameProblem(preset.name, *schema); !why.empty()) throw FileRefused{why};
  if (!root.contains("values")) throw FileRefused{"no \"values\" object"};
  if (std::string why = checkedValues(root["values"], *schema, preset.values); !why.empty()) throw FileRefused{why};
  for (const auto& [key, value] : root.items())
    if (key != "version" && key != "scene" && key != "name" && key != "values")
      throw FileRefused{fmt::format("\"{}\" is not part of a preset", printable(key))};
  return preset;
}

}  // namespace

std::string presetNameProblem(std::string_view name, const Schema& schema) {
  if (name.empty()) return "a preset needs a name";
  if (name.size() > kMaxPresetName)
    return fmt::format("the name '{}...' is longer than {} characters", printable(name.substr(0, 20)), kMaxPresetName);
  if (std::any_of(name.begin(), name.end(), [](char c) { return c < 0x20 || c >= 0x7f; }))
    return fmt::format("the name '{}' holds characters that are not printable ASCII", printable(name));
  if (name.front() == ' ' || name.back() == ' ') return fmt::format("the name '{}' begins or ends with a space", name);
  // --preset SCENE.NAME splits at the '.', and --set KEY=VALUE is told from a preset by its '='.
  if (name.find_first_of(".=") != std::string_view::npos)
    return fmt::format("the name '{}' holds '.' or '=', which --preset SCENE.NAME cannot tell apart", name);
  if (schema.findPreset(name))
    return fmt::format("'{}' is one of the scene's own presets; choose another name", name);
  return {};
}

PresetRead readPresetFile(const fs::path& path, const SchemaLookup& schemaFor) {
  PresetRead read;
  try {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) throw FileRefused{ec ? ec.message() : "not a regular file"};
    read.preset = presetOf(readJsonFile(path, kMaxPresetBytes), schemaFor);
  } catch (const FileRefused& refused) {
    read.why = fmt::format("{} is not a preset ({})", path.string(), refused.why);
  } catch (const std::exception& e) {  // memory, a library's surprise: a refusal like any other
    read.why = fmt::format("{} could not be read ({})", path.string(), e.what());
  }
  return read;
}

void writePresetFile(const fs::path& path, const UserPreset& preset, const SchemaLookup& schemaFor) {
  Json out = Json::object();
  out["version"] = kPresetVersion;
  out["scene"] = preset.scene;
  out["name"] = preset.name;
  out["values"] = valuesObject(schemaFor ? schemaFor(preset.scene) : nullptr, preset.values);
  writeJsonFile(path, out);
}

PresetStore::PresetStore(fs::path folder, SchemaLookup schemaFor, LoadMode mode)
    : folder_(std::move(folder)), schemaFor_(std::move(schemaFor)) {
  std::error_code ec;
  if (folder_.empty() || !fs::is_directory(folder_, ec)) return;  // none saved yet
  std::vector<fs::path> files;
  for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json") files.push_back(it->path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    PresetRead read = readPresetFile(file, schemaFor_);
    if (read.preset && !find(read.preset->scene, read.preset->name)) {
      presets_.push_back(std::move(*read.preset));
    } else if (read.preset) {
      warnings_.push_back(fmt::format("{}: a second preset '{}' of {}; ignored", file.string(), read.preset->name,
                                      read.preset->scene));
    } else {
      warnings_.push_back(fmt::format("{}; {}", read.why, mode == LoadMode::MoveBadAside ? moveAside(file) : "left as it is"));
    }
  }
}

std::vector<const UserPreset*> PresetStore::presetsOf(std::string_view scene) const {
  std::vector<const UserPreset*> out;
  for (const UserPreset& preset : presets_)
    if (preset.scene == scene) out.push_back(&preset);
  std::sort(out.begin(), out.end(), [](const UserPreset* a, const UserPreset* b) { return a->name < b->name; });
  return out;
}

const UserPreset* PresetStore::find(std::string_view scene, std::string_view name) const {
  for (const UserPreset& preset : presets_)
    if (preset.scene == scene && preset.name == name) return &preset;
  return nullptr;
}

fs::path PresetStore::fileOf(std::string_view scene, std::string_view name) const {
  std::string file = std::string(scene) + "-";
  for (const char c : name) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || c == '-' || c == '_') file += c;
    else file += fmt::format("%{:02X}", byte);
  }
  return folder_ / (file + ".json");
}

// The same check a file gets when it is read back: a preset is saved only if it would load.
std::string PresetStore::check(const UserPreset& preset) const {
  const Schema* schema = schemaFor_ ? schemaFor_(preset.scene) : nullptr;
  if (!schema) return fmt::format("no scene '{}'", printable(preset.scene));
  if (std::string why = presetNameProblem(preset.name, *schema); !why.empty()) return why;
  KeyValues kept;
  return checkedValues(valuesObject(schema, preset.values), *schema, kept);
}

std::string PresetStore::save(const UserPreset& preset) {
  if (folder_.empty()) return "no settings folder to keep presets in (neither XDG_CONFIG_HOME nor HOME is set)";
  if (std::string why = check(preset); !why.empty()) return why;
  if (!find(preset.scene, preset.name) && presetsOf(preset.scene).size() >= kMaxPresetsPerScene)
    return fmt::format("{} already has {} presets of yours, as many as are kept; delete one first",
                       printable(preset.scene), kMaxPresetsPerScene);
  try {
    writePresetFile(fileOf(preset.scene, preset.name), preset, schemaFor_);
  } catch (const std::exception& e) {
    return e.what();
  }
  if (UserPreset* same = const_cast<UserPreset*>(find(preset.scene, preset.name))) *same = preset;
  else presets_.push_back(preset);
  return {};
}

std::string PresetStore::rename(std::string_view scene, std::string_view from, std::string_view to) {
  const UserPreset* old = find(scene, from);
  if (!old) return fmt::format("{} has no preset of yours named '{}'", scene, printable(from));
  if (from == to) return {};
  if (find(scene, to)) return fmt::format("{} already has a preset of yours named '{}'", scene, printable(to));
  UserPreset renamed = *old;
  renamed.name = std::string(to);
  if (std::string why = save(renamed); !why.empty()) return why;
  return remove(scene, from);
}

std::string PresetStore::remove(std::string_view scene, std::string_view name) {
  const auto it = std::find_if(presets_.begin(), presets_.end(),
                               [&](const UserPreset& p) { return p.scene == scene && p.name == name; });
  if (it == presets_.end()) return fmt::format("{} has no preset of yours named '{}'", scene, printable(name));
  std::error_code ec;
  fs::remove(fileOf(scene, name), ec);
  if (ec) return fmt::format("Cannot delete {}: {}", fileOf(scene, name).string(), ec.message());
  presets_.erase(it);
  return {};
}

std::string PresetStore::exportTo(std::string_view scene, std::string_view name, const fs::path& path) const {
  const UserPreset* preset = find(scene, name);
  if (!preset) return fmt::format("{} has no preset of yours named '{}'", scene, printable(name));
  try {
    writePresetFile(path, *preset, schemaFor_);
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

std::string PresetStore::import(const fs::path& path) {
  PresetRead read = readPresetFile(path, schemaFor_);
  if (!read.preset) return read.why;
  return save(*read.preset);
}

}  // namespace vitrine::params
