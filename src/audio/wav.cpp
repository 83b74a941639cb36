#include "audio/wav.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <system_error>

#include "audio/synth.h"
#include "core/atomic_file.h"
#include "core/error.h"

namespace vitrine::audio {
namespace {

constexpr uint32_t kChannels = 2;

// WAVE is little-endian whatever the machine is, so every number is written byte by byte.
void put16(std::string& out, uint16_t v) {
  out += char(v & 0xff);
  out += char(v >> 8);
}
void put32(std::string& out, uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) out += char((v >> shift) & 0xff);
}

}  // namespace

void writeWav(const std::filesystem::path& path, std::span<const float> samples, WavFormat format) {
  if (samples.size() % kChannels != 0)
    throw Error(fmt::format("Cannot write {}: {} samples are not whole stereo frames", path.string(), samples.size()));
  size_t at = 0;
  writeWav(path, int64_t(samples.size() / kChannels), [&](int64_t frames) {
    const std::span<const float> stretch = samples.subspan(at, size_t(frames) * kChannels);
    at += stretch.size();
    return stretch;
  }, format);
}

void writeWav(const std::filesystem::path& path, int64_t frames,
              const std::function<std::span<const float>(int64_t frames)>& next, WavFormat format) {
  const bool pcm = format == WavFormat::Pcm16;
  const uint32_t bytesPerSample = pcm ? 2 : 4;
  // IEEE float is not PCM, so its "fmt " chunk carries the extension size (0) and a "fact" chunk
  // gives the frame count, as the WAVE specification asks of every non-PCM format.
  const uint32_t fmtSize = pcm ? 16 : 18;
  const uint32_t headerAfterRiff = 4 + (8 + fmtSize) + (pcm ? 0 : 12) + 8;  // "WAVE", chunks, data's header
  const uint64_t dataBytes = uint64_t(frames) * kChannels * bytesPerSample;
  if (dataBytes + headerAfterRiff > UINT32_MAX)
    throw Error(fmt::format("Cannot write {}: {:.0f} seconds of sound pass the 4 GiB a WAVE file can hold",
                            path.string(), double(frames) / kSampleRate));

  std::string header;
  header += "RIFF";
  put32(header, uint32_t(headerAfterRiff + dataBytes));
  header += "WAVE";
  header += "fmt ";
  put32(header, fmtSize);
  put16(header, pcm ? 1 : 3);  // WAVE_FORMAT_PCM, WAVE_FORMAT_IEEE_FLOAT
  put16(header, kChannels);
  put32(header, kSampleRate);
  put32(header, kSampleRate * kChannels * bytesPerSample);  // bytes per second
  put16(header, uint16_t(kChannels * bytesPerSample));      // bytes per frame
  put16(header, uint16_t(bytesPerSample * 8));              // bits per sample
  if (!pcm) {
    put16(header, 0);
    header += "fact";
    put32(header, 4);
    put32(header, uint32_t(frames));
  }
  header += "data";
  put32(header, uint32_t(dataBytes));

  replaceAtomically(path, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out.write(header.data(), std::streamsize(header.size()));
    std::string chunk;  // converted in pieces, so a long sound needs no second copy in memory
    for (int64_t first = 0; first < frames && out; first += 32768) {
      const int64_t count = std::min<int64_t>(32768, frames - first);
      const std::span<const float> stretch = next(count);
      if (stretch.size() != size_t(count) * kChannels)
        throw Error(fmt::format("Cannot write {}: its sound stopped after {} of {} frames", path.string(),
                                first + int64_t(stretch.size() / kChannels), frames));
      chunk.clear();
      for (float s : stretch) {
        if (pcm)
          put16(chunk, uint16_t(int16_t(std::lround(std::clamp(std::isnan(s) ? 0.0f : s, -1.0f, 1.0f) * 32767.0f))));
        else
          put32(chunk, std::bit_cast<uint32_t>(s));
      }
      out.write(chunk.data(), std::streamsize(chunk.size()));
    }
    out.close();
    if (!out) throw Error(fmt::format("Cannot write {}: {}", path.string(), osReason(errno)));
  });
}

}  // namespace vitrine::audio
