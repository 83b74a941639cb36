#pragma once
// What the record runs share, whether they write a numbered sequence (record.cpp) or a film
// (record_film.cpp): the offscreen run's settings, a frame averaged over its samples, the film's sound,
// and the progress line.
#include "app/options.h"
#include "audio/engine.h"
#include "host/event_log.h"
#include "host/live_link.h"
#include "host/offline/offscreen.h"
#include "live/audio_clip.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::host {

// The scene, size, start, seed, parameters and step of a record run: 1 / (fps x spp). Input, events,
// sound and live input are attached with RecordInputs.
OffscreenConfig recordConfig(const Options& options);

// What a record run feeds its scene and gathers from it besides pictures: the --input script, the
// --events log, the sound, live input (--map, --audio-in, --midi-in). Made in place, attached to the
// run's config, and kept for as long as the run.
struct RecordInputs {
  RecordInputs(const Options& options, OffscreenConfig& config);
  RecordInputs(const RecordInputs&) = delete;
  RecordInputs& operator=(const RecordInputs&) = delete;
  std::string inputText;  // the script's bytes, for record.json's fingerprint
  std::optional<JsonLinesEventLog> events;
  audio::OfflineAudio sound;
  std::unique_ptr<LiveLink> live;
};

// One frame of the film: `spp` steps rendered, their pictures averaged (motion blur and anti-aliasing
// at once). With `keep` false the steps are only simulated (a later frame depends on them) and the
// picture is empty.
ImageRgba renderFrame(Offscreen& offscreen, uint32_t spp, bool keep = true);

// The film's sound as the film goes: the scene's own, rendered a stretch at a time from the commands
// its frames have posted, and the film's music (--audio-in) from the film's first moment, mixed, as
// interleaved 48 kHz stereo; exactly round(seconds x 48000) frames in all, sample for sample what
// rendering it whole after the last frame would give (OfflineRender) as long as each stretch ends at
// least kSoundLag behind the frames simulated.
class FilmSound {
 public:
  // How far a stretch stays behind the simulation: a scene stamps a sound with the time its cause
  // happened, which it may learn a few steps later (bloom's bells ring at phase changes read back from
  // the GPU, up to four steps late). Half a second is hundreds of steps at any rate a film is made at.
  static constexpr double kSoundLag = 0.5;

  // Whether the film has sound so far: the scene made some, or there is music.
  static bool any(const audio::OfflineAudio& sound, const LiveLink* live);

  FilmSound(const audio::OfflineAudio& sound, const LiveLink* live, double start, double seconds);
  FilmSound(const FilmSound&) = delete;
  FilmSound& operator=(const FilmSound&) = delete;

  // The frames from the last stretch's end up to the film's frame `until` (counted from its first
  // sample, cut to the length), valid until the next call.
  std::span<const float> next(int64_t until);
  // How far a stretch may reach once the simulation has passed `seconds` into the film: kSoundLag behind.
  static int64_t behind(double seconds);
  int64_t frames() const { return scene_.frames(); }
  int64_t rendered() const { return scene_.rendered(); }
  // Sounds the scene stamped too far back to land on their sample (see kSoundLag): none, or the film's
  // sound differs from a whole render's.
  size_t late() const { return scene_.late(); }

 private:
  audio::OfflineRender scene_;
  std::optional<live::Stereo48kStream> music_;
  std::vector<float> stretch_, musicStretch_;
};

// The whole film's sound, once its last frame is done, into `path` as 16-bit WAV, a stretch at a time
// (an hour is never whole in memory). False, and nothing written, when the film has no sound.
bool writeFilmSound(const std::filesystem::path& path, const audio::OfflineAudio& sound, const LiveLink* live,
                    double start, double seconds);

// Progress on stderr: a bar redrawn in place on a terminal, a line every tenth otherwise (logs).
class RecordProgress {
 public:
  explicit RecordProgress(uint32_t total);
  void update(uint32_t done, uint32_t written);

 private:
  uint32_t total_;
  bool terminal_;
  uint32_t lastTenth_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace vitrine::host
