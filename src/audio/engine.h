#pragma once
// The sound engine. A Synth renders stereo blocks on the audio thread from commands that the frame
// loop posts through a lock-free queue; AudioOutput plays one on the default device (or stays
// silent when there is none), OfflineAudio renders a run sample-exactly for --audio-out.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "audio/audio_sink.h"
#include "audio/sound_tap.h"
#include "audio/spsc_queue.h"
#include "audio/synth.h"

class RtAudio;

namespace vitrine::audio {

// A command's time for "as soon as possible": before any sample, so it applies at the start of
// the next block rendered.
inline constexpr int64_t kAsSoonAsPossible = std::numeric_limits<int64_t>::min();

// Sample time for simulation seconds (seconds x 48000, rounded); a non-finite time means "as soon
// as possible".
int64_t sampleTime(double seconds);

struct Command {
  enum class Kind : uint8_t { Bell, Climax, Drone, Volume, Mute, ReverbWet };
  Kind kind = Kind::Bell;
  int64_t sample = kAsSoonAsPossible;  // applies before this sample is rendered
  // Bell: pitch in Hz. Drone, Mute: 1 on, 0 off. Volume: master gain 0..1.
  // ReverbWet: a fixed wet amount 0..1, or NaN to give the wet back to the climax automation.
  float value = 0.0f;
};

// Renders the mix: drone + bell voices -> plate reverb (wet/dry crossfade:
// (1 - wet) x dry + wet x reverb) -> master volume and mute -> limiter; mono, written to both
// channels. Commands are posted by one producer thread and applied by render() at their exact
// sample, also in the middle of a block. Commands must be posted in order of time (the frame loop
// does): render() looks only at the oldest, so an earlier time behind a later one waits for it.
class Synth {
 public:
  static constexpr size_t kQueueCapacity = 1024;
  static constexpr size_t kVoices = 16;  // bells ringing at once; a seventeenth steals the oldest

  explicit Synth(int64_t firstSample = 0, uint32_t reverbSeed = kPlateSeed);

  // Producer side (one thread). False when the queue is full and the command was dropped.
  bool post(const Command& command) { return queue_.push(command); }

  // Consumer side (the audio thread): exactly `frames` interleaved stereo frames. Never locks,
  // waits or allocates.
  void render(float* interleavedStereo, size_t frames);

  // Consumer-side state, for tests and offline use on the rendering thread.
  int64_t now() const { return now_; }  // the sample render() produces next
  float wet() const { return wet_.value(); }
  size_t ringing() const;  // active bell voices

  // Music played under the mix, looped (the gallery's --audio-in): interleaved stereo at 48 kHz,
  // owned by the caller and unchanged while set. Set from any thread; null stops it.
  void setMusic(const std::vector<float>* stereo) { music_.store(stereo, std::memory_order_release); }
  uint64_t musicFrames() const { return musicPlayed_.load(std::memory_order_relaxed); }  // frames played so far

 private:
  void apply(const Command& command);
  void startBell(float hz, float level, std::span<const Partial> partials);
  void renderSpan(float* out, size_t frames);

  SpscQueue<Command, kQueueCapacity> queue_;
  Drone drone_;
  std::array<BellVoice, kVoices> voices_;
  PartitionedConvolver reverb_;
  WetEnvelope wet_;
  Ramp volume_{1.0f}, unmuted_{1.0f};
  Limiter limiter_;
  int64_t now_;
  std::atomic<const std::vector<float>*> music_{nullptr};
  size_t musicAt_ = 0;  // the next music frame (audio thread)
  std::atomic<uint64_t> musicPlayed_{0};
};

// Plays a Synth on the default output device through RtAudio, 48 kHz stereo float. Without a
// device (none found, none opens) it prints one warning, "vitrine: no audio device (REASON):
// running silent", and every call is a no-op; it never throws for want of sound. Use from one
// thread (the frame loop). Scene calls ignore their time and play as soon as possible.
class AudioOutput final : public AudioSink {
 public:
  struct Options {
    bool useDevice = true;        // false: behave exactly as on a machine with no device
    unsigned bufferFrames = 512;  // 10.7 ms per callback; the device may choose another size
  };
  AudioOutput();
  explicit AudioOutput(Options options);
  ~AudioOutput() override;
  AudioOutput(const AudioOutput&) = delete;
  AudioOutput& operator=(const AudioOutput&) = delete;

  bool silent() const { return !device_; }
  // Stops and restarts the stream (the gallery while minimised): no callbacks, no CPU.
  void pause();
  void resume();
  bool paused() const { return paused_; }
  // Glide to silence and back over 20 ms.
  void setMuted(bool muted);
  bool muted() const { return muted_; }
  void setVolume(float gain);

  void bell(double time, float hz) override;
  void climax(double time, float wet) override;
  void volume(double time, float gain) override;
  void drone(double time, bool on) override;
  void reverb(double time, std::optional<float> wet) override;

  // Loops `stereo` (48 kHz, interleaved) under the scenes' sound, muted with them: the sound file that
  // drives live input (--audio-in), heard as it plays. Once per output.
  void playMusic(std::vector<float> stereo);
  // Seconds of the music heard so far (the device's clock; the wall clock without a device): where
  // the analysis of the file is, so the picture follows what is heard.
  double musicSeconds() const;

  // A copy of what the device plays from the first call on, for a live stream, read by the caller.
  // Without a device, the synth is made at the first call and plays to nobody: renderUnheard renders
  // it on the caller's clock instead, and the tap stays empty.
  SoundTap& tap();
  // Without a device, after tap(): the synth's next `frames` interleaved stereo frames. Nothing with
  // a device (its callback renders them into the tap).
  void renderUnheard(float* stereo, size_t frames);

  // What the device's callback reads: the synth it renders, and where it copies what it played.
  struct Playing {
    Synth* synth = nullptr;
    std::atomic<SoundTap*> tap{nullptr};
  };

 private:
  std::string open(const Options& options);  // the reason it failed, or empty
  void post(Command::Kind kind, float value);

  // Member order matters: the device's callback renders the synth and writes the tap, so the device
  // goes first.
  std::unique_ptr<Synth> synth_;
  std::unique_ptr<SoundTap> tap_;
  Playing playing_;
  std::unique_ptr<RtAudio> device_;
  bool paused_ = false, muted_ = false;
  std::vector<float> music_;
  std::chrono::steady_clock::time_point musicStart_{};
};

// Collects a run's commands with their simulation times and renders it afterwards, each command
// at its exact sample: the sound of a headless run, for --audio-out.
class OfflineAudio final : public AudioSink {
 public:
  // `startTime`: the simulation time of the first sample (the run's --time).
  explicit OfflineAudio(double startTime = 0.0, uint32_t reverbSeed = kPlateSeed);

  void bell(double time, float hz) override;
  void climax(double time, float wet) override;
  void drone(double time, bool on) override;
  void reverb(double time, std::optional<float> wet) override;
  void volume(double time, float gain) override;
  // Any command, already stamped with its sample time.
  void post(const Command& command);

  // The run's sound from startTime: exactly round(seconds x 48000) interleaved stereo frames.
  // Commands before startTime apply at its first sample, those after the end are left out.
  // Renders afresh each call. Throws vitrine::Error for a negative or non-finite length.
  std::vector<float> render(double seconds) const;
  // How many commands the scene gave: none means a silent scene (no WAV worth writing).
  size_t commandCount() const { return commands_.size(); }
  // Every command so far, in order: a checkpoint keeps them, and a run resumed from it posts them again.
  const std::vector<Command>& commands() const { return commands_; }
  int64_t firstSample() const { return firstSample_; }
  uint32_t reverbSeed() const { return reverbSeed_; }

 private:
  void add(Command::Kind kind, double time, float value);
  int64_t firstSample_;
  uint32_t reverbSeed_;
  std::vector<Command> commands_;
};

// An OfflineAudio's sound rendered a stretch at a time while its run goes on, so a film's sound is
// written as its frames are: sample for sample what OfflineAudio::render gives for the same length,
// wherever the stretches end, provided each command reaches the OfflineAudio before the stretch that
// holds its sample is rendered. One that comes later (a scene stamping a time further back than the
// caller's lag allows) plays at the next sample rendered instead, and is counted.
class OfflineRender {
 public:
  // Throws vitrine::Error for a negative or non-finite length, as render does. Reads `sound`'s
  // commands at each renderTo, so it must outlive this.
  OfflineRender(const OfflineAudio& sound, double seconds);
  OfflineRender(const OfflineRender&) = delete;
  OfflineRender& operator=(const OfflineRender&) = delete;

  // Appends to `out` the interleaved stereo frames from rendered() up to `until` (counted from the
  // first sample, cut to the length), with the commands posted so far.
  void renderTo(int64_t until, std::vector<float>& out);
  int64_t rendered() const;
  int64_t frames() const { return frames_; }  // round(seconds x 48000)
  size_t late() const { return late_; }

 private:
  const OfflineAudio& sound_;
  int64_t frames_;
  std::unique_ptr<Synth> synth_;
  size_t taken_ = 0;              // commands of sound_ moved into pending_
  std::vector<Command> pending_;  // taken, not yet posted to the synth; in order of time, stably
  size_t late_ = 0;
};

}  // namespace vitrine::audio
