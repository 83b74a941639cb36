#include "host/gallery_settings.h"

#include <fmt/format.h>

#include <cstdio>

#include "core/error.h"
#include "scenes/scene.h"

namespace vitrine::host {

const params::Schema* schemaOfScene(std::string_view scene) {
  const SceneInfo* info = findScene(scene);
  return info ? &info->schema() : nullptr;
}

GallerySettings::GallerySettings(std::filesystem::path path, bool reset) : path_(std::move(path)) {
  if (path_.empty()) {
    warnings_.push_back("no settings folder (neither XDG_CONFIG_HOME nor HOME is set): settings are not kept");
    return;
  }
  if (reset) return;
  params::LoadResult loaded = params::loadSettings(path_, schemaOfScene);
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
  stored = std::move(values);
  saver_.markDirty(now);
}

void GallerySettings::showing(std::string_view scene, Clock::time_point now) {
  if (settings_.scene == scene) return;
  settings_.scene = std::string(scene);
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
    params::saveSettings(path_, settings_, schemaOfScene);
  } catch (const Error& e) {  // a full disk or a read-only home must not end the session
    warnings_.push_back(e.what());
    std::fprintf(stderr, "vitrine: %s\n", e.what());
  }
}

}  // namespace vitrine::host
