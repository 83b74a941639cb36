#pragma once
// Live sound from a capture device through RtAudio (audio/engine.cpp plays through it too): by
// default what the computer itself is playing, so a gallery follows the music in the room's
// speakers without a microphone.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "live/audio_analysis.h"

namespace vitrine::live {

// Without a device (none found, none opens, or useDevice false) it prints one line, "vitrine: no
// audio input (REASON): live audio off", is inactive and take() returns zeros; it never throws for
// want of sound. Use from one thread (the frame loop); the device's thread only fills a lock-free ring.
class AudioCapture {
 public:
  struct Options {
    // Empty: the monitor of the default output where the system offers one (PulseAudio: the stream
    // is opened with PULSE_SOURCE=@DEFAULT_MONITOR@ unless the user has set PULSE_SOURCE), else the
    // default input. Else a device index or a case-insensitive part of its name (inputDevices()).
    std::string device;
    bool useDevice = true;  // false: behave exactly as with no device (tests)
    unsigned bufferFrames = 256;  // 5.3 ms at 48 kHz; the device may choose another size
  };
  // Seconds of sound the ring holds between two take()s; more is dropped (a stalled frame loop).
  static constexpr double kRingSeconds = 1.0;

  explicit AudioCapture(Options options);
  ~AudioCapture();
  AudioCapture(const AudioCapture&) = delete;
  AudioCapture& operator=(const AudioCapture&) = delete;

  bool active() const;
  // "capturing NAME, 48000 Hz, 256-frame buffer" or "no audio input (REASON)".
  std::string status() const;
  // Drains what the device captured since the last call into the analyser and returns its take();
  // `tap`, when given, sees the same mono samples first (LTC is read from them). Inactive: all zero.
  AudioFeatures take(const std::function<void(std::span<const float>)>& tap = {});
  // The device's sample rate; 0 when inactive.
  double sampleRate() const;
  // The capture buffer's length in ms (a part of the input's latency, with the analyser's); 0 when
  // inactive.
  double bufferMs() const;
  // The analyser (its onset and beat times); nullptr when inactive.
  const AudioAnalyser* analyser() const;
  // Samples dropped because take() was not called for more than kRingSeconds.
  uint64_t droppedSamples() const;

  // Devices with input channels, "INDEX: NAME", for --help and error messages. Empty without any.
  static std::vector<std::string> inputDevices();


 private:
  struct Device;  // the open stream, its ring and analyser
  std::string open(const Options& options);  // the reason it failed, or empty
  std::unique_ptr<Device> device_;
  std::string status_;
};

}  // namespace vitrine::live
