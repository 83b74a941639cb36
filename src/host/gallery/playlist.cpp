#include "host/gallery/playlist.h"

#include "core/bounded_file.h"
#include "core/error.h"
#include "core/printable.h"
#include "params/preset_store.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace vitrine::host {
namespace {

constexpr uintmax_t kMaxPlaylistBytes = 1u << 20;

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view text) {
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  return text;
}

// "at HH:MM:SS:FF " before the rest of a chased line: the timecode read into entry.at, the rest left.
std::string parseAt(std::string_view& line, PlaylistEntry& entry) {
  line.remove_prefix(3);
  line = trim(line);
  size_t end = 0;
  while (end < line.size() && !blank(line[end])) ++end;
  std::string why;
  entry.at = rig::parseTimecode(line.substr(0, end), &why);
  if (!entry.at) return fmt::format("'at {}': {}", printable(line.substr(0, end)), why);
  line = trim(line.substr(end));
  if (line.empty()) return "'at TIMECODE' wants a scene after it (e.g. 'at 00:01:30:00 kifs sphere')";
  entry.dwell = kMaxPlaylistDwell;
  return {};
}

// "SCENE [PRESET...] DWELL" or "at HH:MM:SS:FF SCENE [PRESET...]", or why not.
std::string parseLine(std::string_view line, const PlaylistChecks& checks, PlaylistEntry& entry) {
  for (const char c : line)
    if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
      return fmt::format("'{}' holds a control character", printable(line));
  const bool chased = line.size() > 3 && line.starts_with("at") && blank(line[2]);
  if (chased)
    if (std::string why = parseAt(line, entry); !why.empty()) return why;
  size_t sceneEnd = 0;
  while (sceneEnd < line.size() && !blank(line[sceneEnd])) ++sceneEnd;
  size_t dwellStart = line.size();
  while (!chased && dwellStart > 0 && !blank(line[dwellStart - 1])) --dwellStart;
  if (!chased && dwellStart <= sceneEnd)
    return fmt::format("'{}' is not SCENE [PRESET] SECONDS (e.g. 'kifs sphere 30')", printable(line));
  entry.scene = line.substr(0, sceneEnd);
  entry.preset = trim(line.substr(sceneEnd, dwellStart - sceneEnd));
  const std::string_view dwell = line.substr(dwellStart);
  if (chased) {
    // A chased line's length is its frame's business; nothing to read here.
  } else if (const auto [end, ec] = std::from_chars(dwell.data(), dwell.data() + dwell.size(), entry.dwell);
             ec != std::errc() || end != dwell.data() + dwell.size() || !std::isfinite(entry.dwell) ||
             !(entry.dwell > 0.0) || entry.dwell > kMaxPlaylistDwell) {
    return fmt::format("the dwell '{}' is not a number of seconds above 0 and at most {}", printable(dwell),
                       kMaxPlaylistDwell);
  }
  if (!checks.sceneExists || !checks.sceneExists(entry.scene))
    return fmt::format("no scene '{}'; vitrine --list-scenes shows them", printable(entry.scene));
  // A name no preset can have is refused here, quoted safely: the checks below quote it as it is.
  if (entry.preset.size() > params::kMaxPresetName ||
      std::any_of(entry.preset.begin(), entry.preset.end(), [](char c) { return c < 0x20 || c >= 0x7f; }))
    return fmt::format("'{}' is no preset's name (printable ASCII, at most {} characters)", printable(entry.preset),
                       params::kMaxPresetName);
  if (!entry.preset.empty() && checks.presetProblem)
    if (std::string why = checks.presetProblem(entry.scene, entry.preset); !why.empty()) return why;
  return {};
}

}  // namespace

std::vector<PlaylistEntry> parsePlaylist(std::string_view text, std::string_view where, const PlaylistChecks& checks) {
  std::vector<PlaylistEntry> entries;
  size_t number = 0;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte-order mark, as editors write
  while (!text.empty()) {
    const size_t eol = text.find('\n');
    const std::string_view line = trim(text.substr(0, eol));
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    ++number;
    if (line.empty() || line.front() == '#') continue;
    PlaylistEntry entry;
    if (std::string why = parseLine(line, checks, entry); !why.empty())
      throw Error(fmt::format("{}:{}: {}.", where, number, why));
    if (entries.size() == kMaxPlaylistEntries)
      throw Error(fmt::format("{}:{}: more than {} entries.", where, number, kMaxPlaylistEntries));
    if (!entries.empty() && entries.front().at.has_value() != entry.at.has_value())
      throw Error(fmt::format("{}:{}: a playlist is chased by timecode ('at HH:MM:SS:FF SCENE [PRESET]' on every "
                              "line) or timed by dwells ('SCENE [PRESET] SECONDS' on every line), not both.",
                              where, number));
    // Compared as 30 a second: every rate orders labels the same way.
    const auto order = [](const rig::Timecode& t) { return *rig::frameCount(t, rig::FrameRate::Fps30); };
    if (entry.at && !entries.empty() && order(*entry.at) <= order(*entries.back().at))
      throw Error(fmt::format("{}:{}: at {} is not after the line before's {}; chased lines go in time order.", where,
                              number, rig::formatTimecode(*entry.at), rig::formatTimecode(*entries.back().at)));
    entries.push_back(std::move(entry));
  }
  if (entries.empty()) throw Error(fmt::format("{}: no entries; a line is SCENE [PRESET] SECONDS.", where));
  return entries;
}

bool chasedByTimecode(const std::vector<PlaylistEntry>& playlist) {
  return !playlist.empty() && playlist.front().at.has_value();
}

std::vector<PlaylistEntry> loadPlaylist(const std::filesystem::path& path, const PlaylistChecks& checks) {
  try {
    return parsePlaylist(readBoundedFile(path, kMaxPlaylistBytes), path.string(), checks);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("--playlist {}: {}.", path.string(), refused.why));
  }
}

}  // namespace vitrine::host
