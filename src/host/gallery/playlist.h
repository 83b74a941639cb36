#pragma once
// A kiosk's playlist (--playlist FILE): which scene shows, with which preset, for how long, e.g.
//
//   # the evening programme
//   kifs sphere 20
//   kifs final 40
//   noodles 45                  (no preset: the scene's saved values)
//   bloom my evening look 30    (a preset of the user's: a name may hold spaces)
//
// One entry a line: the scene first, the dwell in seconds last, the preset's name (built-in or the
// user's) whatever is between. Blank lines and lines starting with '#' are skipped. Every line is
// checked before the window opens; the first bad one refuses the file, naming its line. Pure logic:
// the caller says which scenes and presets exist.
//
// A playlist chased by timecode (MIDI timecode or LTC, host/gallery/timecode_chase.h) gives each line
// the frame it starts on instead of a dwell; it shows until the next line's frame:
//
//   at 00:00:00:00 kifs sphere
//   at 00:01:30:00 noodles
//   at 00:02:10:12 bloom my evening look
//
// Every line of such a playlist starts with `at HH:MM:SS:FF`, each later than the one before.
#include "rig/timecode.h"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

struct PlaylistEntry {
  std::string scene;
  std::string preset;  // empty: none
  double dwell = 0.0;  // seconds, above 0; a chased line's: kMaxPlaylistDwell (its frame decides)
  std::optional<rig::Timecode> at;  // the frame a chased line starts on
  bool operator==(const PlaylistEntry&) const = default;
};

inline constexpr size_t kMaxPlaylistEntries = 1000;
inline constexpr double kMaxPlaylistDwell = 86400.0;  // as --dwell

struct PlaylistChecks {
  std::function<bool(std::string_view scene)> sceneExists;
  // Why `scene` has no preset `name` (a sentence listing what it has); empty when it has.
  std::function<std::string(std::string_view scene, std::string_view name)> presetProblem;
};

// Throws vitrine::Error "WHERE:LINE: why" for the first bad line, or "WHERE: no entries".
// A playlist's lines all have `at` or none does.
std::vector<PlaylistEntry> parsePlaylist(std::string_view text, std::string_view where, const PlaylistChecks& checks);
// Reads the file (at most 1 MiB) and parses it; throws vitrine::Error naming the file.
std::vector<PlaylistEntry> loadPlaylist(const std::filesystem::path& path, const PlaylistChecks& checks);
// The playlist is chased by timecode (its lines have `at`).
bool chasedByTimecode(const std::vector<PlaylistEntry>& playlist);

}  // namespace vitrine::host
