#pragma once
// The one sound file Vitrine writes: a RIFF/WAVE file, stereo at 48 kHz.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>

namespace vitrine::audio {

enum class WavFormat {
  Pcm16,    // 16-bit signed integers: plays anywhere; samples are clamped to [-1, 1] and rounded
  Float32,  // 32-bit IEEE floats, exactly what was rendered
};

// Writes interleaved stereo samples (left, right, left, ...) atomically: a reader sees the old file
// or the whole new one. Throws vitrine::Error naming the file when it cannot be written, when the
// samples are not whole frames, or when the data would pass WAVE's 4 GiB limit.
void writeWav(const std::filesystem::path& path, std::span<const float> interleavedStereo,
              WavFormat format = WavFormat::Pcm16);
// The same for `frames` stereo frames taken a stretch at a time: next(n) gives the next n frames,
// interleaved (valid until the next call), so a long sound is written without ever being whole in memory.
void writeWav(const std::filesystem::path& path, int64_t frames,
              const std::function<std::span<const float>(int64_t frames)>& next, WavFormat format = WavFormat::Pcm16);

}  // namespace vitrine::audio
