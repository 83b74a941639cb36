#include "host/filters/filter_options.h"
#include "host/offline/record_shared.h"
#include "host/user_presets.h"

#include "host/modes.h"

#include "audio/wav.h"
#include "live/audio_clip.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace vitrine::host {

OffscreenConfig recordConfig(const Options& options) {
  OffscreenConfig config{options.scene, options.size.value_or(kRecordSize), options.time, options.seed,
                         options.reducedMotion, presetsFor(options, options.scene, true),
                         parametersFor(options, options.scene, true)};
  config.flashGuard = flashGuardOn(options);
  config.filters = filterSpecs(options);
  config.presetFiles = presetFilesFor(options, options.scene);
  config.step = 1.0 / (options.fps * double(options.spp));
  return config;
}

RecordInputs::RecordInputs(const Options& options, OffscreenConfig& config)
    : sound(options.time), live(offlineLiveInput(options, options.scene)) {
  if (!options.input.empty()) config.input = loadInputScript(options.input, &inputText);
  if (!options.events.empty()) config.events = &events.emplace(options.events);
  config.audio = &sound;
  config.live = live.get();
}

ImageRgba renderFrame(Offscreen& offscreen, uint32_t spp, bool keep) {
  ImageRgba sum;
  for (uint32_t sample = 0; sample < spp; ++sample) {
    offscreen.renderFrame(1, keep);  // a frame not kept is simulated, not drawn
    if (!keep) continue;
    const ImageRgba image = offscreen.readback();
    if (sum.pixels.empty()) sum = image;
    else for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += image.pixels[i];
  }
  if (keep && spp > 1)
    for (float& v : sum.pixels) v /= float(spp);
  return sum;
}

bool FilmSound::any(const audio::OfflineAudio& sound, const LiveLink* live) {
  return sound.commandCount() > 0 || (live && live->audioClip());
}

FilmSound::FilmSound(const audio::OfflineAudio& sound, const LiveLink* live, double start, double seconds)
    : scene_(sound, seconds) {
  if (const live::AudioClip* music = live ? live->audioClip() : nullptr) music_.emplace(*music, start);
}

int64_t FilmSound::behind(double seconds) { return std::max<int64_t>(0, audio::toSamples(seconds - kSoundLag)); }

std::span<const float> FilmSound::next(int64_t until) {
  stretch_.clear();
  scene_.renderTo(until, stretch_);
  if (music_) {
    musicStretch_.resize(stretch_.size());
    music_->next(musicStretch_.data(), musicStretch_.size() / 2);
    for (size_t i = 0; i < stretch_.size(); ++i) stretch_[i] += musicStretch_[i];
  }
  return stretch_;
}

bool writeFilmSound(const std::filesystem::path& path, const audio::OfflineAudio& sound, const LiveLink* live,
                    double start, double seconds) {
  if (!FilmSound::any(sound, live)) return false;
  FilmSound film(sound, live, start, seconds);
  audio::writeWav(path, film.frames(), [&](int64_t frames) { return film.next(film.rendered() + frames); });
  return true;
}

RecordProgress::RecordProgress(uint32_t total) : total_(total), terminal_(isatty(fileno(stderr))) {}

void RecordProgress::update(uint32_t done, uint32_t written) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double rate = seconds > 0.0 ? double(done) / seconds : 0.0;
  const double left = rate > 0.0 ? double(total_ - done) / rate : 0.0;
  const std::string line = fmt::format("{}/{} frames ({} written), {:.1f} frames/s, {:.0f} s left", done, total_,
                                       written, rate, left);
  if (terminal_) {
    const int width = 30, filled = int(std::lround(width * double(done) / double(std::max(total_, 1u))));
    std::fprintf(stderr, "\r[%s%s] %s ", std::string(size_t(filled), '#').c_str(),
                 std::string(size_t(width - filled), '.').c_str(), line.c_str());
    if (done == total_) std::fputc('\n', stderr);
  } else if (done == total_ || done * 10 / std::max(total_, 1u) != lastTenth_) {
    lastTenth_ = done * 10 / std::max(total_, 1u);
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
}

}  // namespace vitrine::host
