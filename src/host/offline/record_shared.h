#pragma once
// What the record runs share, whether they write a numbered sequence (record.cpp) or a film
// (record_film.cpp): the offscreen run's settings, a frame averaged over its samples, the film's sound,
// and the progress line.
#include "app/options.h"
#include "audio/engine.h"
#include "host/event_log.h"
#include "host/live_link.h"
#include "host/offline/offscreen.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
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

// The film's sound: the scene's own and the film's music (--audio-in) from the film's first moment,
// mixed, as interleaved 48 kHz stereo of exactly round(seconds x 48000) frames. Empty when the scene
// made no sound and there is no music.
std::vector<float> filmSound(const audio::OfflineAudio& sound, const LiveLink* live, double start, double seconds);

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
