#include "live/audio_capture.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>

#include "audio/rtaudio_stream.h"
#include "core/hidden_stderr.h"
#include "live/float_ring.h"

namespace vitrine::live {

namespace {

constexpr unsigned kPreferredRate = 48000;
constexpr const char* kMonitor = "@DEFAULT_MONITOR@";

// The stream's error callback (audio/rtaudio_stream.h).
void streamError(RtAudioError::Type type, const std::string& message) {
  static std::atomic_flag told;
  if (audio::stopsTheStream(type) && !told.test_and_set())
    std::fprintf(stderr, "vitrine: audio input stopped (%s): live audio off\n", message.c_str());
}

// PULSE_SOURCE=@DEFAULT_MONITOR@ while a PulseAudio stream opens (libpulse reads it then), unless
// the user set PULSE_SOURCE; put back afterwards, so nothing else in the process sees it.
class MonitorSource {
 public:
  explicit MonitorSource(bool wanted) : set_(wanted && !std::getenv("PULSE_SOURCE")) {
    if (set_) ::setenv("PULSE_SOURCE", kMonitor, 1);
  }
  ~MonitorSource() {
    if (set_) ::unsetenv("PULSE_SOURCE");
  }
  MonitorSource(const MonitorSource&) = delete;
  MonitorSource& operator=(const MonitorSource&) = delete;

 private:
  bool set_;
};

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Device infos by index; a device whose probe throws is left out (RtAudio 5 throws for one it
// cannot open while listing).
std::vector<std::optional<RtAudio::DeviceInfo>> probe(RtAudio& audio) {
  std::vector<std::optional<RtAudio::DeviceInfo>> infos(audio.getDeviceCount());
  for (unsigned i = 0; i < infos.size(); ++i) {
    try {
      RtAudio::DeviceInfo info = audio.getDeviceInfo(i);
      if (info.probed) infos[i] = std::move(info);
    } catch (const RtAudioError&) {
    }
  }
  return infos;
}

}  // namespace

struct AudioCapture::Device {
  explicit Device(double requestedRate) : ring(size_t(requestedRate * kRingSeconds)), scratch(4096) {}
  ~Device() {
    if (audio) audio::closeStream(*audio);
  }

  // The audio thread: mixes the channels to mono and hands them to the ring. No locks, no
  // allocation, no waiting; what the ring cannot hold is dropped (and counted).
  static int callback(void*, void* input, unsigned frames, double, RtAudioStreamStatus, void* self) {
    auto& device = *static_cast<Device*>(self);
    const auto* in = static_cast<const float*>(input);
    if (!in) return 0;
    float mono[512];
    const unsigned channels = device.channels;
    while (frames > 0) {
      const unsigned n = std::min<unsigned>(frames, std::size(mono));
      for (unsigned i = 0; i < n; ++i) {
        float sum = 0;
        for (unsigned c = 0; c < channels; ++c) sum += in[i * channels + c];
        mono[i] = sum / float(channels);
      }
      device.ring.push(std::span<const float>(mono, n));
      in += size_t(n) * channels;
      frames -= n;
    }
    return 0;
  }

  FloatRing ring;
  std::optional<AudioAnalyser> analyser;  // made once the stream's own rate is known
  std::vector<float> scratch;  // the frame loop's side: drained samples on their way to the analyser
  unsigned channels = 1, rate = 0, bufferFrames = 0;
  std::string name;
  // Last, so it is destroyed (its stream closed) before the ring the callback writes to.
  std::unique_ptr<RtAudio> audio;
};

AudioCapture::AudioCapture(Options options) {
  const std::string reason = options.useDevice ? open(options) : "not asked to open one";
  if (!reason.empty()) {
    status_ = fmt::format("no audio input ({})", reason);
    std::fprintf(stderr, "vitrine: no audio input (%s): live audio off\n", reason.c_str());
  } else {
    status_ = fmt::format("capturing {}, {} Hz, {}-frame buffer", device_->name, device_->rate,
                          device_->bufferFrames);
  }
}

AudioCapture::~AudioCapture() = default;

std::string AudioCapture::open(const Options& options) {
  try {
    HiddenStderr hidden;
    auto audio = std::make_unique<RtAudio>();
    audio->showWarnings(false);
    const auto infos = probe(*audio);
    if (infos.empty()) return "none found";
    const auto hasInput = [&](unsigned i) { return i < infos.size() && infos[i] && infos[i]->inputChannels > 0; };

    unsigned id = 0;
    const std::string& wanted = options.device;
    if (wanted.empty()) {
      id = audio->getDefaultInputDevice();
      if (!hasInput(id)) {
        id = 0;
        while (id < infos.size() && !hasInput(id)) ++id;
        if (id == infos.size()) return "no device has input channels";
      }
    } else if (std::all_of(wanted.begin(), wanted.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
      id = unsigned(std::min<unsigned long>(std::strtoul(wanted.c_str(), nullptr, 10), ~0u));
      if (!hasInput(id)) return fmt::format("device {} is not one with input channels", wanted);
    } else {
      id = 0;
      while (id < infos.size() && !(hasInput(id) && lower(infos[id]->name).find(lower(wanted)) != std::string::npos))
        ++id;
      if (id == infos.size()) return fmt::format("no input device is named like '{}'", wanted);
    }
    const RtAudio::DeviceInfo& info = *infos[id];

    // 48 kHz where the device offers it (the analyser is tuned in Hz, any rate works), else its own.
    unsigned rate = info.preferredSampleRate ? info.preferredSampleRate : kPreferredRate;
    if (info.sampleRates.empty() ||
        std::find(info.sampleRates.begin(), info.sampleRates.end(), kPreferredRate) != info.sampleRates.end())
      rate = kPreferredRate;
    else if (!info.preferredSampleRate)
      rate = info.sampleRates.back();

    RtAudio::StreamParameters input;
    input.deviceId = id;
    input.nChannels = std::min(info.inputChannels, 2u);
    RtAudio::StreamOptions streamOptions;
    streamOptions.streamName = "Vitrine live input";
    const bool pulse = audio->getCurrentApi() == RtAudio::LINUX_PULSE;
    const bool userSource = pulse && std::getenv("PULSE_SOURCE") != nullptr;
    auto device = std::make_unique<Device>(double(rate));
    device->channels = input.nChannels;
    device->bufferFrames = std::max(options.bufferFrames, 16u);
    const auto openWith = [&](bool useMonitor) {
      MonitorSource source(useMonitor);
      audio->openStream(nullptr, &input, RTAUDIO_FLOAT32, rate, &device->bufferFrames, &Device::callback,
                        device.get(), &streamOptions, &streamError);
    };
    bool onMonitor = pulse && wanted.empty() && !userSource;
    try {
      openWith(onMonitor);
    } catch (const RtAudioError&) {
      // A system with no output has no monitor of it: its default input then.
      if (!onMonitor) throw;
      onMonitor = false;
      device->bufferFrames = std::max(options.bufferFrames, 16u);
      openWith(false);
    }
    // From here the device owns the stream and closes it before the ring its callback writes to.
    device->audio = std::move(audio);
    device->rate = device->audio->getStreamSampleRate();
    if (device->rate < 1000 || device->rate > 768000) return fmt::format("the device runs at {} Hz", device->rate);
    device->analyser.emplace(double(device->rate));
    device->name = info.name;
    if (onMonitor) device->name += fmt::format(" ({}, the monitor of the default output)", kMonitor);
    else if (userSource) device->name += fmt::format(" (PULSE_SOURCE={})", std::getenv("PULSE_SOURCE"));
    if (std::string why = audio::startStream(*device->audio); !why.empty()) return why;
    device_ = std::move(device);
    return {};
  } catch (...) {
    return audio::openFailure();
  }
}

bool AudioCapture::active() const { return device_ != nullptr; }

std::string AudioCapture::status() const { return status_; }

AudioFeatures AudioCapture::take(const std::function<void(std::span<const float>)>& tap) {
  if (!device_) return {};
  Device& d = *device_;
  while (const size_t n = d.ring.pop(d.scratch)) {
    const std::span<const float> samples(d.scratch.data(), n);
    if (tap) tap(samples);
    d.analyser->push(samples);
  }
  return d.analyser->take();
}

double AudioCapture::sampleRate() const { return device_ ? double(device_->rate) : 0.0; }

double AudioCapture::bufferMs() const { return device_ ? 1000.0 * device_->bufferFrames / device_->rate : 0.0; }

const AudioAnalyser* AudioCapture::analyser() const { return device_ ? &*device_->analyser : nullptr; }

uint64_t AudioCapture::droppedSamples() const { return device_ ? device_->ring.dropped() : 0; }

std::vector<std::string> AudioCapture::inputDevices() {
  std::vector<std::string> names;
  try {
    HiddenStderr hidden;
    RtAudio audio;
    audio.showWarnings(false);
    const auto infos = probe(audio);
    for (unsigned i = 0; i < infos.size(); ++i)
      if (infos[i] && infos[i]->inputChannels > 0) names.push_back(fmt::format("{}: {}", i, infos[i]->name));
  } catch (const RtAudioError&) {
    // No sound system at all: no devices.
  }
  return names;
}

}  // namespace vitrine::live
