#include "host/gallery/gallery_settings.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <set>

#include "core/error.h"
#include "scenes/catalogue.h"

namespace vitrine::host {

namespace {

// The text a key stands for in a scene's saved values: its own, or its default when the file has none.
std::optional<std::string> effectiveText(std::string_view scene, const params::KeyValues& values, const std::string& key) {
  for (const auto& [k, text] : values)
    if (k == key) return text;
  const params::Schema* schema = findSchema(scene);
  const params::Param* param = schema ? schema->find(key) : nullptr;
  if (!param) return std::nullopt;
  const auto defaults = schema->makeDefaults();
  return param->format(defaults.get());
}

}  // namespace

GallerySettings::GallerySettings(std::filesystem::path path, bool reset, bool keepScene)
    : path_(std::move(path)), keepScene_(keepScene) {
  if (path_.empty()) {
    warnings_.push_back("no settings folder (neither XDG_CONFIG_HOME nor HOME is set): settings are not kept");
    return;
  }
  if (reset) {
    changes_.all = !keepScene_;  // the file starts over at the first save (a kiosk merges, keeping the scene)
    return;
  }
  params::LoadResult loaded = params::loadSettings(path_, findSchema);
  settings_ = std::move(loaded.settings);
  for (auto& warning : loaded.warnings) warnings_.push_back(fmt::format("{}: {}", path_.string(), warning));
}

GallerySettings::~GallerySettings() {
  try {
    flush();
  } catch (const std::exception& e) {  // quitting: say so, do not throw from a destructor
    std::fprintf(stderr, "vitrine: %s\n", e.what());
  }
}

params::KeyValues GallerySettings::valuesFor(std::string_view scene) const {
  const auto it = settings_.scenes.find(std::string(scene));
  return it == settings_.scenes.end() ? params::KeyValues{} : it->second;
}

void GallerySettings::remember(std::string_view scene, params::KeyValues values, Clock::time_point now) {
  auto& stored = settings_.scenes[std::string(scene)];
  if (stored == values) return;
  std::set<std::string>* changed = nullptr;
  const auto mark = [&](const std::string& key) {
    if (!changed) changed = &changes_.keys[std::string(scene)];
    changed->insert(key);
  };
  for (const auto& [key, text] : values)
    if (effectiveText(scene, stored, key) != text) mark(key);
  for (const auto& [key, text] : stored)  // an init-capture: clang 14 (the sanitizer build) cannot capture a binding
    if (std::none_of(values.begin(), values.end(), [&name = key](const auto& kv) { return kv.first == name; })) mark(key);
  stored = std::move(values);
  if (changed) saver_.markDirty(now);
}

void GallerySettings::showing(std::string_view scene, Clock::time_point now) {
  if (keepScene_ || settings_.scene == scene) return;
  settings_.scene = std::string(scene);
  changes_.scene = true;
  saver_.markDirty(now);
}

const std::vector<std::string>& GallerySettings::mappingsFor(std::string_view scene) const {
  static const std::vector<std::string> none;
  const auto it = settings_.mappings.find(std::string(scene));
  return it == settings_.mappings.end() ? none : it->second;
}

void GallerySettings::setMappings(std::string_view scene, std::vector<std::string> lines, Clock::time_point now) {
  if (mappingsFor(scene) == lines) return;
  if (lines.empty()) settings_.mappings.erase(std::string(scene));
  else settings_.mappings[std::string(scene)] = std::move(lines);
  changes_.mappings.insert(std::string(scene));
  saver_.markDirty(now);
}

void GallerySettings::setAudioInput(bool on, std::string device, Clock::time_point now) {
  if (settings_.audioInput == on && settings_.audioDevice == device) return;
  settings_.audioInput = on;
  settings_.audioDevice = std::move(device);
  changes_.live = true;
  saver_.markDirty(now);
}

std::string GallerySettings::lightsPatch() const {
  const auto lights = settings_.unknown.find("lights");
  if (lights == settings_.unknown.end() || !lights->is_object()) return {};
  const auto patch = lights->find("patch");
  return patch != lights->end() && patch->is_string() ? patch->get<std::string>() : std::string();
}

const nlohmann::ordered_json* GallerySettings::warpFor(std::string_view output) const {
  const auto it = settings_.outputs.find(std::string(output));
  return it == settings_.outputs.end() ? nullptr : &it->second;
}

void GallerySettings::setWarp(std::string_view output, nlohmann::ordered_json warp, Clock::time_point now) {
  const nlohmann::ordered_json* had = warpFor(output);
  if (had ? *had == warp : warp.empty()) return;
  if (warp.empty()) settings_.outputs.erase(std::string(output));
  else settings_.outputs[std::string(output)] = std::move(warp);
  changes_.outputs.insert(std::string(output));
  saver_.markDirty(now);
}

const nlohmann::ordered_json* GallerySettings::filtersFor(std::string_view scene) const {
  const auto it = settings_.filters.find(std::string(scene));
  return it == settings_.filters.end() ? nullptr : &it->second;
}

void GallerySettings::setFilters(std::string_view scene, nlohmann::ordered_json chain, Clock::time_point now) {
  const nlohmann::ordered_json* had = filtersFor(scene);
  if (had ? *had == chain : chain.empty()) return;
  if (chain.empty()) settings_.filters.erase(std::string(scene));
  else settings_.filters[std::string(scene)] = std::move(chain);
  changes_.filters.insert(std::string(scene));
  saver_.markDirty(now);
}

void GallerySettings::setTransition(nlohmann::ordered_json transition, Clock::time_point now) {
  if (settings_.transition == transition) return;
  settings_.transition = std::move(transition);
  changes_.transition = true;
  saver_.markDirty(now);
}

void GallerySettings::tick(Clock::time_point now) {
  if (saver_.due(now)) save();
}

void GallerySettings::flush() {
  if (saver_.flush()) save();
}

void GallerySettings::save() {
  if (path_.empty()) return;
  try {
    // Another gallery may have saved since: what it changed stays, unless this one changed it too.
    // A file gone is written from this gallery's values alone; one edited meanwhile into something that
    // is not settings (broken JSON) is moved aside first, as at start, so the edit is kept for a look.
    std::error_code ec;
    params::Settings merged = settings_;
    if (!changes_.all && std::filesystem::exists(path_, ec)) {
      params::LoadResult disk = params::loadSettings(path_, findSchema, params::LoadMode::ReplaceBad);
      if (disk.readable) {
        merged = params::mergeSettings(std::move(disk.settings), settings_, changes_);
      } else {
        for (auto& warning : disk.warnings) {
          std::fprintf(stderr, "vitrine: settings: %s\n", warning.c_str());
          warnings_.push_back(std::move(warning));
        }
      }
    }
    params::saveSettings(path_, merged, findSchema);
    changes_ = {};
  } catch (const std::exception& e) {  // a full disk or a read-only home must not end the session
    warnings_.push_back(e.what());
    std::fprintf(stderr, "vitrine: %s\n", e.what());
  }
}

}  // namespace vitrine::host
