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
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

struct PlaylistEntry {
  std::string scene;
  std::string preset;  // empty: none
  double dwell = 0.0;  // seconds, above 0
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
std::vector<PlaylistEntry> parsePlaylist(std::string_view text, std::string_view where, const PlaylistChecks& checks);
// Reads the file (at most 1 MiB) and parses it; throws vitrine::Error naming the file.
std::vector<PlaylistEntry> loadPlaylist(const std::filesystem::path& path, const PlaylistChecks& checks);

}  // namespace vitrine::host
