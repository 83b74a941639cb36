#include "audio/engine.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "audio/rtaudio_stream.h"
#include "core/error.h"
#include "core/hidden_stderr.h"

namespace vitrine::audio {

int64_t sampleTime(double seconds) { return std::isfinite(seconds) ? toSamples(seconds) : kAsSoonAsPossible; }

// --- Synth ---

Synth::Synth(int64_t firstSample, uint32_t reverbSeed) : reverb_(plateImpulse(reverbSeed)), now_(firstSample) {}

void Synth::render(float* out, size_t frames) {
  while (frames > 0) {
    // Everything due by this sample applies before it is rendered; late commands apply now.
    const Command* next = queue_.front();
    while (next && next->sample <= now_) {
      apply(*next);
      queue_.pop();
      next = queue_.front();
    }
    // Render up to the next command's sample, so it lands exactly there even mid-block.
    size_t span = frames;
    if (next) span = size_t(std::min<int64_t>(int64_t(frames), next->sample - now_));
    renderSpan(out, span);
    out += 2 * span;
    frames -= span;
    now_ += int64_t(span);
  }
}

void Synth::renderSpan(float* out, size_t frames) {
  for (size_t i = 0; i < frames; ++i) {
    float dry = drone_.next();
    for (BellVoice& voice : voices_)
      if (voice.active()) dry += voice.next();
    // The convolver runs even while the mix is dry, so the plate opens on a full tail.
    const float reverberated = reverb_.process(dry);
    const float wet = wet_.next();
    const float mixed = (1.0f - wet) * dry + wet * reverberated;
    const float unmuted = unmuted_.next();
    const float sample = limiter_.process(mixed * volume_.next() * unmuted);
    out[2 * i] = sample;
    out[2 * i + 1] = sample;
    if (const std::vector<float>* music = music_.load(std::memory_order_acquire); music && music->size() >= 2) {
      if (2 * musicAt_ + 1 >= music->size()) musicAt_ = 0;
      out[2 * i] = std::clamp(sample + (*music)[2 * musicAt_] * unmuted, -1.0f, 1.0f);
      out[2 * i + 1] = std::clamp(sample + (*music)[2 * musicAt_ + 1] * unmuted, -1.0f, 1.0f);
      ++musicAt_;
      musicPlayed_.fetch_add(1, std::memory_order_relaxed);
    }
  }
}

void Synth::apply(const Command& command) {
  switch (command.kind) {
    case Command::Kind::Bell:
      startBell(command.value, kBellLevel, kBellPartials);
      break;
    case Command::Kind::Climax:
      for (float hz : kClimaxChordHz) startBell(hz, kClimaxLevel, kClimaxPartials);
      wet_.climax(command.value);
      break;
    case Command::Kind::Drone:
      drone_.setOn(command.value != 0.0f);
      break;
    case Command::Kind::Volume:
      if (std::isfinite(command.value)) volume_.set(std::clamp(command.value, 0.0f, 1.0f), kLevelGlide);
      break;
    case Command::Kind::Mute:
      unmuted_.set(command.value != 0.0f ? 0.0f : 1.0f, kLevelGlide);
      break;
    case Command::Kind::ReverbWet:
      wet_.setOverride(std::isnan(command.value) ? std::nullopt : std::optional<float>(command.value));
      break;
  }
}

void Synth::startBell(float hz, float level, std::span<const Partial> partials) {
  if (!(hz > 0.0f && hz < kSampleRate / 2.0f)) return;  // NaN included: nothing sensible to ring
  BellVoice* voice = &voices_[0];
  for (BellVoice& candidate : voices_) {
    if (!candidate.active()) {
      voice = &candidate;
      break;
    }
    // The oldest has decayed furthest, so cutting it off is the least audible.
    if (candidate.started() < voice->started()) voice = &candidate;
  }
  voice->start(hz, level, partials, now_);
}

size_t Synth::ringing() const {
  return size_t(std::count_if(voices_.begin(), voices_.end(), [](const BellVoice& v) { return v.active(); }));
}

// --- AudioOutput ---

namespace {

int playCallback(void* output, void*, unsigned int frames, double, RtAudioStreamStatus, void* playing) {
  auto& p = *static_cast<AudioOutput::Playing*>(playing);
  p.synth->render(static_cast<float*>(output), frames);
  if (SoundTap* tap = p.tap.load(std::memory_order_acquire)) tap->write(static_cast<const float*>(output), frames);
  return 0;
}

// The stream's error callback (rtaudio_stream.h), and what pause and resume do when they fail.
void streamError(RtAudioError::Type type, const std::string& message) {
  static std::atomic_flag told;
  if (stopsTheStream(type) && !told.test_and_set())
    std::fprintf(stderr, "vitrine: audio stopped (%s): running silent\n", message.c_str());
}

}  // namespace

AudioOutput::AudioOutput() : AudioOutput(Options{}) {}

void AudioOutput::playMusic(std::vector<float> stereo) {
  if (!music_.empty()) return;  // once: the audio thread may be reading it
  music_ = std::move(stereo);
  musicStart_ = std::chrono::steady_clock::now();
  if (synth_) synth_->setMusic(&music_);
}

double AudioOutput::musicSeconds() const {
  if (synth_ && device_) return double(synth_->musicFrames()) / double(kSampleRate);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - musicStart_).count();
}

AudioOutput::AudioOutput(Options options) {
  const std::string reason = options.useDevice ? open(options) : "not asked to open one";
  if (!reason.empty()) std::fprintf(stderr, "vitrine: no audio device (%s): running silent\n", reason.c_str());
}

std::string AudioOutput::open(const Options& options) {
  auto synth = std::make_unique<Synth>();
  try {
    HiddenStderr hidden;
    auto device = std::make_unique<RtAudio>();
    device->showWarnings(false);
    if (device->getDeviceCount() == 0) return "none found";
    RtAudio::StreamParameters output;
    output.deviceId = device->getDefaultOutputDevice();
    output.nChannels = 2;
    RtAudio::StreamOptions streamOptions;
    streamOptions.streamName = "Vitrine";
    unsigned int frames = options.bufferFrames;
    playing_.synth = synth.get();
    device->openStream(&output, nullptr, RTAUDIO_FLOAT32, kSampleRate, &frames, &playCallback, &playing_,
                       &streamOptions, &streamError);
    if (std::string why = startStream(*device); !why.empty()) return why;
    synth_ = std::move(synth);
    device_ = std::move(device);
    return {};
  } catch (...) {
    return openFailure();
  }
}

AudioOutput::~AudioOutput() {
  if (!device_) return;
  closeStream(*device_);
}

void AudioOutput::pause() {
  if (!device_ || paused_) return;
  paused_ = true;
  try {
    device_->stopStream();
  } catch (const RtAudioError& e) {
    streamError(RtAudioError::SYSTEM_ERROR, e.getMessage());
  }
}

void AudioOutput::resume() {
  if (!device_ || !paused_) return;
  paused_ = false;
  try {
    device_->startStream();
  } catch (const RtAudioError& e) {
    streamError(RtAudioError::SYSTEM_ERROR, e.getMessage());
  }
}

SoundTap& AudioOutput::tap() {
  if (tap_) return *tap_;
  tap_ = std::make_unique<SoundTap>();
  if (device_) {
    playing_.tap.store(tap_.get(), std::memory_order_release);
  } else if (!synth_) {
    synth_ = std::make_unique<Synth>();
    if (!music_.empty()) synth_->setMusic(&music_);
  }
  return *tap_;
}

void AudioOutput::renderUnheard(float* stereo, size_t frames) {
  if (!device_ && synth_) synth_->render(stereo, frames);
}

void AudioOutput::setMuted(bool muted) {
  muted_ = muted;
  post(Command::Kind::Mute, muted ? 1.0f : 0.0f);
}

void AudioOutput::setVolume(float gain) { post(Command::Kind::Volume, gain); }

void AudioOutput::bell(double, float hz) { post(Command::Kind::Bell, hz); }
void AudioOutput::climax(double, float wet) { post(Command::Kind::Climax, wet); }
void AudioOutput::volume(double, float gain) { setVolume(gain); }
void AudioOutput::drone(double, bool on) { post(Command::Kind::Drone, on ? 1.0f : 0.0f); }
void AudioOutput::reverb(double, std::optional<float> wet) { post(Command::Kind::ReverbWet, wet.value_or(NAN)); }

void AudioOutput::post(Command::Kind kind, float value) {
  // A full queue means the callback has not run for 1024 commands (a paused stream): dropping a
  // sound then is better than blocking the frame loop.
  if (synth_) synth_->post({kind, kAsSoonAsPossible, value});
}

// --- OfflineAudio ---

OfflineAudio::OfflineAudio(double startTime, uint32_t reverbSeed)
    : firstSample_(std::isfinite(startTime) ? toSamples(startTime) : 0), reverbSeed_(reverbSeed) {}

void OfflineAudio::bell(double time, float hz) { add(Command::Kind::Bell, time, hz); }
void OfflineAudio::climax(double time, float wet) { add(Command::Kind::Climax, time, wet); }
void OfflineAudio::drone(double time, bool on) { add(Command::Kind::Drone, time, on ? 1.0f : 0.0f); }
void OfflineAudio::reverb(double time, std::optional<float> wet) {
  add(Command::Kind::ReverbWet, time, wet.value_or(NAN));
}
void OfflineAudio::volume(double time, float gain) { add(Command::Kind::Volume, time, gain); }

void OfflineAudio::add(Command::Kind kind, double time, float value) { post({kind, sampleTime(time), value}); }

void OfflineAudio::post(const Command& command) { commands_.push_back(command); }

std::vector<float> OfflineAudio::render(double seconds) const {
  OfflineRender whole(*this, seconds);
  std::vector<float> out;
  out.reserve(size_t(whole.frames()) * 2);
  whole.renderTo(whole.frames(), out);
  return out;
}

// --- OfflineRender ---

OfflineRender::OfflineRender(const OfflineAudio& sound, double seconds) : sound_(sound) {
  if (!std::isfinite(seconds) || seconds < 0.0)
    throw Error(fmt::format("Cannot render {} seconds of sound: the length must be a finite number from 0", seconds));
  frames_ = toSamples(seconds);
  synth_ = std::make_unique<Synth>(sound.firstSample(), sound.reverbSeed());
}

int64_t OfflineRender::rendered() const { return synth_->now() - sound_.firstSample(); }

void OfflineRender::renderTo(int64_t until, std::vector<float>& out) {
  const std::vector<Command>& commands = sound_.commands();
  if (taken_ < commands.size()) {
    // Commands before the first sample apply at it, as long as nothing has been rendered yet.
    for (size_t i = taken_; i < commands.size(); ++i) {
      if (rendered() > 0 && commands[i].sample < synth_->now()) ++late_;
      pending_.push_back(commands[i]);
    }
    taken_ = commands.size();
    // The synth wants its commands in order of time; scenes may interleave sources, so sort (stably:
    // two commands for one sample keep the order they were given in, those taken earlier first).
    std::stable_sort(pending_.begin(), pending_.end(),
                     [](const Command& a, const Command& b) { return a.sample < b.sample; });
  }
  const int64_t from = synth_->now(), end = sound_.firstSample() + std::clamp(until, rendered(), frames_);
  const size_t at = out.size();
  out.resize(at + size_t(end - from) * 2);
  size_t next = 0;
  while (synth_->now() < end) {
    int64_t blockEnd = std::min(synth_->now() + 4096, end);
    while (next < pending_.size() && pending_[next].sample < blockEnd && synth_->post(pending_[next])) ++next;
    // A full queue (over a thousand commands in one block): render up to the first that did not fit.
    if (next < pending_.size() && pending_[next].sample < blockEnd)
      blockEnd = std::max(pending_[next].sample, synth_->now() + 1);
    synth_->render(out.data() + at + 2 * size_t(synth_->now() - from), size_t(blockEnd - synth_->now()));
  }
  pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(next));
}

}  // namespace vitrine::audio
