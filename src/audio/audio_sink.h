#pragma once
// What a scene may ask of the sound, without knowing whether it is played on a device (the
// gallery: AudioOutput in engine.h) or rendered into a file (--audio-out: OfflineAudio), or
// dropped (SilentAudio). Times are simulation seconds, the clock a scene's update sees: an offline
// render starts each sound on exactly that sample; a device plays it as soon as it can.
#include <optional>

namespace vitrine::audio {

// The bloom scene's bell pitches (Hz): up-crossings ring E4, B4, E5 in turn.
inline constexpr float kE4 = 329.63f;
inline constexpr float kB4 = 493.88f;
inline constexpr float kE5 = 659.26f;

class AudioSink {
 public:
  virtual ~AudioSink() = default;
  // One bell at `hz`: 3 ms attack, 1.8 s decay to -60 dB.
  virtual void bell(double time, float hz) = 0;
  // The four-bell climax chord; opens the plate reverb to `wet` (the write-up's 0.28) for six seconds.
  virtual void climax(double time, float wet) = 0;
  // Master gain, 0 (silent) .. 1, gliding over 20 ms.
  virtual void volume(double time, float gain) = 0;
  // The 55 Hz drone, faded in or out over half a second. It starts off.
  virtual void drone(double time, bool on) = 0;
  // Fixes the reverb's wet amount (0 dry .. 1 all reverb), or with nullopt hands it back to the
  // climax automation. Changes glide over 0.3 s.
  virtual void reverb(double time, std::optional<float> wet) = 0;
};

// For runs with no sound at all: headless without --audio-out, bench, tests.
class SilentAudio final : public AudioSink {
 public:
  void bell(double, float) override {}
  void climax(double, float) override {}
  void volume(double, float) override {}
  void drone(double, bool) override {}
  void reverb(double, std::optional<float>) override {}
};

}  // namespace vitrine::audio
