#include "host/gallery/kiosk_timetable.h"

#include <glm/geometric.hpp>

#include <algorithm>

#include "core/error.h"

namespace vitrine::host {
namespace {

size_t registryIndex(const SceneInfo& info) { return size_t(&info - sceneRegistry().data()); }

KioskTiming timingFor(double dwell) { return {dwell, KioskTimetable::kFadeSeconds, std::clamp(dwell, 10.0, 30.0)}; }

std::vector<const SceneInfo*> scenesOf(const std::vector<PlaylistEntry>& playlist) {
  std::vector<const SceneInfo*> scenes;
  for (const PlaylistEntry& entry : playlist) {
    scenes.push_back(findScene(entry.scene));
    if (!scenes.back()) throw Error(unknownScene(entry.scene));
  }
  return scenes;
}

KioskSchedule scheduleFor(const std::vector<PlaylistEntry>& playlist, const SceneInfo& first, double dwell) {
  if (playlist.empty()) return KioskSchedule(sceneRegistry().size(), registryIndex(first), timingFor(dwell));
  std::vector<double> dwells;
  for (const PlaylistEntry& entry : playlist) dwells.push_back(entry.dwell);
  const double shortest = *std::min_element(dwells.begin(), dwells.end());
  return KioskSchedule(std::move(dwells), 0, timingFor(shortest));
}

}  // namespace

KioskTimetable::KioskTimetable(std::vector<PlaylistEntry> playlist, const SceneInfo& first, double dwell)
    : playlist_(std::move(playlist)), scenes_(scenesOf(playlist_)), schedule_(scheduleFor(playlist_, first, dwell)) {}

const SceneInfo& KioskTimetable::sceneOf(size_t entry) const {
  return playlist_.empty() ? sceneRegistry()[entry] : *scenes_[entry];
}

// Its first line in a playlist (the line showing when none is).
size_t KioskTimetable::entryOf(const SceneInfo& scene) const {
  if (playlist_.empty()) return registryIndex(scene);
  for (size_t entry = 0; entry < scenes_.size(); ++entry)
    if (scenes_[entry] == &scene) return entry;
  return schedule_.current();
}

bool KioskTimetable::touched(const Pointer& pointer, bool keysOrDrops) {
  const bool moved = pointer.inside && glm::length(pointer.pixels - lastPointer_.pixels) > 2.0f;
  lastPointer_ = pointer;
  return moved || pointer.leftPressed || pointer.leftHeld || pointer.wheel != 0.0f || keysOrDrops;
}

const SceneInfo& KioskTimetable::failed(const SceneInfo& scene) {
  for (size_t entry = 0; entry < entries(); ++entry)
    if (&sceneOf(entry) == &scene) schedule_.failed(entry);
  return sceneOf(schedule_.current());
}

size_t KioskTimetable::showing(const SceneInfo& scene) {
  const size_t entry = &sceneOf(schedule_.current()) == &scene ? schedule_.current() : entryOf(scene);
  schedule_.jumpTo(entry);
  return entry;
}

const PlaylistEntry* KioskTimetable::presetOf(size_t entry, std::string_view scene) const {
  if (entry >= playlist_.size() || playlist_[entry].preset.empty() || playlist_[entry].scene != scene) return nullptr;
  return &playlist_[entry];
}

}  // namespace vitrine::host
