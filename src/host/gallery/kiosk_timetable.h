#pragma once
// Kiosk mode's timetable (--kiosk): what shows and when. It turns the kiosk's entries (the registry's
// scenes in turn, or a playlist's lines, host/gallery/playlist.h) and its schedule (host/gallery/kiosk.h) into scenes,
// tells a person's touch from a cursor at rest, and keeps the schedule in step with the scene the
// gallery shows (a number key, a phone, a scene that would not start). No GPU: the gallery starts the
// scenes it names, the cross-fade (host/gallery/kiosk_crossfade.h) mixes them.
//
// The schedule runs on the seconds advance() is given: the gallery passes the wall clock's time since
// the last frame. Another clock (beats, timecode) drives it through the same call.
#include "host/gallery/kiosk.h"
#include "host/gallery/playlist.h"
#include "host/pointer.h"
#include "scenes/scene.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace vitrine::host {

class KioskTimetable {
 public:
  // Cycling resumes after 30 s alone, or the shortest dwell when shorter (but 10 s at least); a fade
  // takes kFadeSeconds.
  static constexpr double kFadeSeconds = 2.0;
  // `playlist` empty: every registered scene in turn from `first`, each for `dwell` seconds; else the
  // playlist's lines in order from its first (which `first` is), each for its own dwell. Throws
  // vitrine::Error for a playlist line naming a scene this build lacks.
  KioskTimetable(std::vector<PlaylistEntry> playlist, const SceneInfo& first, double dwell);

  // A playlist's presets apply over the saved values and are not remembered, so that a line without a
  // preset shows the scene as saved, whatever an earlier line set.
  bool playlist() const { return !playlist_.empty(); }
  size_t entries() const { return playlist_.empty() ? sceneRegistry().size() : playlist_.size(); }
  const SceneInfo& sceneOf(size_t entry) const;
  size_t current() const { return schedule_.current(); }

  // Did a person do anything this frame? A key, a click, a scroll, a drop (`keysOrDrops`), or a mouse
  // that moved. The first pointer the gallery gives is where the cursor rests (rest()).
  bool touched(const Pointer& pointer, bool keysOrDrops);
  void rest(const Pointer& pointer) { lastPointer_ = pointer; }

  // Once a frame, `elapsed` seconds on: whether a fade begins (the entry whose scene comes in), goes on
  // or finishes.
  KioskSchedule::Plan advance(double elapsed, bool touched, bool mayBegin = true) {
    return schedule_.advance(elapsed, touched, mayBegin);
  }
  // A chased playlist's line whose frame has come: faded in from the next advance(), or made current
  // at once when `cut` (the gallery then shows its scene).
  void cue(size_t entry, bool cut) {
    if (cut) schedule_.jumpTo(entry);
    else schedule_.cue(entry);
  }
  // `entry` failed to start as the incoming scene: skipped from now on, its fade ended.
  void failed(size_t entry) { schedule_.failed(entry); }
  // `scene` failed to start where the gallery shows its scene: every entry of it is skipped. Returns the
  // scene to try instead; `scene` itself when nothing else is left.
  const SceneInfo& failed(const SceneInfo& scene);
  // `scene` shows now, chosen directly: the entry showing when it is this scene's, else the scene's first
  // entry, made current (no fade). Returns that entry.
  size_t showing(const SceneInfo& scene);
  // The playlist line whose preset goes over `scene`'s saved values once it started for `entry`; null
  // when none does (no playlist, no preset, or the entry is another scene's).
  const PlaylistEntry* presetOf(size_t entry, std::string_view scene) const;

 private:
  size_t entryOf(const SceneInfo& scene) const;
  std::vector<PlaylistEntry> playlist_;
  std::vector<const SceneInfo*> scenes_;  // the playlist's, line by line
  KioskSchedule schedule_;
  Pointer lastPointer_;  // to tell a moved mouse
};

}  // namespace vitrine::host
