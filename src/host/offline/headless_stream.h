#pragma once
// A headless run's --stream: each frame read back and handed to the stream as it is rendered, paced at
// 60 a second of wall time, with the run's sound (the scene's, rendered offline a stretch at a time,
// and --audio-in's music) on the same clock.
#include "app/options.h"
#include "audio/engine.h"
#include "film/stream_sender.h"
#include "host/live_link.h"
#include "host/offline/offscreen.h"
#include "host/offline/record_shared.h"

#include <cstdint>

namespace vitrine::host {

class HeadlessStream {
 public:
  // `sound` and `live` must outlive this; the run is `frames` frames of 1/60 s.
  HeadlessStream(const Options& options, VkExtent2D size, const audio::OfflineAudio& sound, const LiveLink* live,
                 uint32_t frames);
  // Frame `index` of the run, just rendered: read back and pushed with the sound up to it.
  void frame(Offscreen& offscreen, uint32_t index);
  // The rest of the sound, then the stream's counts on stdout.
  void finish(uint32_t rendered);

 private:
  // The sound stays this far behind the frames: a scene stamps a sound with the time its cause
  // happened, which it may learn a few frames later (film/FilmSound says more).
  static constexpr double kSoundLag = 0.1;

  film::StreamSender sender_;
  FilmSound sound_;
};

}  // namespace vitrine::host
