#pragma once
// What a film is encoded as, decided from its name and the command line before any frame renders: the
// container, the video codec and FFmpeg's encoder for it, the pixel format, the quality and the sound's
// codec. No FFmpeg here, so every refusal is a sentence the unit tests read, given before any work.
#include <cstdint>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace vitrine::film {

enum class Container { Mp4, Mov, Mkv };
enum class Codec { H264, Hevc, Prores, Prores4444, Ffv1 };

// What the command line asked for (--codec, --crf, --bitrate, --pix-fmt, --full-range); what is not
// given takes the container's and the codec's defaults.
struct FilmRequest {
  FilmRequest() {}  // not an aggregate: GCC 12 at -O3 warns of an uninitialised pixelFormat in Options{} otherwise
  std::optional<Codec> codec;
  std::optional<int> crf;
  std::optional<int64_t> bitrate;  // bits a second
  std::string pixelFormat;         // FFmpeg's name; empty: the codec's own
  bool fullRange = false;
  std::string preset;              // x264/x265's speed for its quality ("veryfast"); empty: medium
};

// Everything the encoder needs, checked against the container and the frame size.
struct FilmFormat {
  Container container = Container::Mp4;
  Codec codec = Codec::H264;
  std::string muxer;        // FFmpeg's muxer: "mp4", "mov", "matroska"
  std::string encoder;      // FFmpeg's encoder: "libx264", "libx265", "prores_ks", "ffv1"
  std::string pixelFormat;  // "yuv420p", "yuv422p10le", "bgr0", ...
  bool deep = false;        // more than 8 bits a channel: frames go in as 16-bit sRGB, not 8-bit
  bool rgb = false;         // stored as RGB (ffv1): no matrix, always full range
  bool fullRange = false;   // Y'CbCr over 0..255 (pc), not 16..235 (tv)
  std::optional<int> crf;   // h264, hevc: exactly one of crf and bitrate is set
  std::optional<int64_t> bitrate;
  std::string preset;       // h264, hevc: x264/x265's preset ("medium")
  std::string proresProfile;  // prores_ks's "hq" or "4444"
  std::string audioEncoder;   // "aac" beside h264 and hevc; "pcm_s24le" beside prores and ffv1
};

// How a frame's display values lie when they reach the encoder: packed RGB at 8 bits (the Y'CbCr
// films' converter input), B, G, R, 0 at 8 bits (an RGB film's own layout), packed RGB at 16 bits
// (a 10-bit film's converter input), or R, G, B, 0 at 8 bits (a hardware encoder's input). Values as
// shaders/host/film_pack_blocks.h's FILM_PACK_*; displayLayout is a software encoder's.
enum class DisplayLayout : uint32_t { Rgb24 = 0, Bgr0 = 1, Rgb48 = 2, Rgb0 = 3 };
DisplayLayout displayLayout(const FilmFormat& format);
uint32_t bytesPerPixel(DisplayLayout layout);

// The container a film's name asks for, from its extension in any case; nothing for any other name.
std::optional<Container> containerFromName(const std::filesystem::path& path);
bool isFilmName(const std::filesystem::path& path);
// x264's and x265's presets, fastest first: each trades encoding time for bytes at the same quality.
inline constexpr std::array<std::string_view, 9> kEncoderPresets{"ultrafast", "superfast", "veryfast", "faster", "fast",
                                                                 "medium",    "slow",      "slower",   "veryslow"};
// The extension, lower case, of a name that is a sound's, a picture's or a film's this build does not
// write (".mp3", ".webm", ".png"): not a folder of frames either. Empty for any other name.
std::string otherMediaExtension(const std::filesystem::path& path);

std::string_view codecName(Codec codec);
// --codec's value; throws vitrine::Error listing the codecs for anything else.
Codec parseCodec(std::string_view text);
// --bitrate's value: bits a second, with k (thousands) or M (millions): "8M", "2500k", "1.5M".
// Throws vitrine::Error for anything else, zero, or more than 1000M.
int64_t parseBitrate(std::string_view text);

// The format of a film named `target` of width x height frames. Throws vitrine::Error for a name
// that is not a film's, a codec the container does not hold, a pixel format the codec does not take,
// a quality setting the codec has none of, and a size the chroma subsampling cannot halve.
FilmFormat resolveFilm(const std::filesystem::path& target, const FilmRequest& request, uint32_t width,
                       uint32_t height);

}  // namespace vitrine::film
