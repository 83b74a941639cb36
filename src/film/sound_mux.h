#pragma once
// A film's second pass: its encoded video copied packet for packet (no re-encoding) beside its sound,
// encoded here, both streams starting at the film's first instant.
#include <filesystem>
#include <span>
#include <string>

#include "film/film_format.h"

namespace vitrine::film {

// Writes `out` (a new file, in `format`'s container) from the video-only film `videoOnly` and the
// interleaved 48 kHz stereo `stereo48k`, encoded as format.audioEncoder (AAC or 24-bit PCM) and cut or
// padded with silence to exactly round(seconds x 48000) frames, so both streams end together. Packets
// are interleaved by time as they are written. Throws vitrine::Error naming `target`.
void muxWithSound(const std::filesystem::path& videoOnly, const std::filesystem::path& out, const std::string& target,
                  const FilmFormat& format, std::span<const float> stereo48k, double seconds);

}  // namespace vitrine::film
