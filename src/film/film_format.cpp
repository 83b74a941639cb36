#include "film/film_format.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "core/error.h"

namespace vitrine::film {
namespace {

constexpr std::array kCodecs{std::pair{Codec::H264, std::string_view("h264")}, std::pair{Codec::Hevc, std::string_view("hevc")},
                             std::pair{Codec::Prores, std::string_view("prores")},
                             std::pair{Codec::Prores4444, std::string_view("prores4444")},
                             std::pair{Codec::Ffv1, std::string_view("ffv1")}};

// The pixel formats --pix-fmt may pick for h264 and hevc (both encoders take all four).
constexpr std::array<std::string_view, 4> kYuvFormats{"yuv420p", "yuv444p", "yuv420p10le", "yuv444p10le"};

constexpr int64_t kMaxBitrate = 1'000'000'000;

std::string lowercase(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string_view extensionOf(Container container) {
  switch (container) {
    case Container::Mp4: return ".mp4";
    case Container::Mov: return ".mov";
    case Container::Mkv: return ".mkv";
  }
  return "";
}

// Which codecs each container holds here: MP4 is for delivery (h264, hevc); QuickTime adds ProRes;
// Matroska takes all of them, and is the only one FFmpeg writes FFV1 into.
bool holds(Container container, Codec codec) {
  switch (container) {
    case Container::Mp4: return codec == Codec::H264 || codec == Codec::Hevc;
    case Container::Mov: return codec != Codec::Ffv1;
    case Container::Mkv: return true;
  }
  return false;
}

std::string heldList(Container container) {
  switch (container) {
    case Container::Mp4: return "h264 or hevc";
    case Container::Mov: return "h264, hevc, prores or prores4444";
    case Container::Mkv: return "h264, hevc, prores, prores4444 or ffv1";
  }
  return "";
}

// Where a codec the container does not hold can go instead.
std::string_view homeOf(Codec codec) { return codec == Codec::Ffv1 ? ".mkv" : ".mov (or .mkv)"; }

Codec defaultCodec(Container container) {
  switch (container) {
    case Container::Mp4: return Codec::H264;
    case Container::Mov: return Codec::Prores;
    case Container::Mkv: return Codec::Ffv1;
  }
  return Codec::H264;
}

bool isDelivery(Codec codec) { return codec == Codec::H264 || codec == Codec::Hevc; }

// Subsampled chroma keeps one sample for two pixels across (4:2:2) or for a 2x2 block (4:2:0): an odd
// side would leave half a block that encoders refuse or crop.
void checkSubsampling(const std::string& pixelFormat, uint32_t width, uint32_t height) {
  const bool both = pixelFormat.find("420") != std::string::npos;
  const bool across = both || pixelFormat.find("422") != std::string::npos;
  if ((across && width % 2 != 0) || (both && height % 2 != 0))
    throw Error(fmt::format("{} halves the colour {}, so it needs an even {}, not {}x{}; record at {}x{}{}.",
                            pixelFormat, both ? "across and down" : "across",
                            both ? "width and height" : "width", width, height, width + width % 2,
                            both ? height + height % 2 : height,
                            both ? " or use --pix-fmt yuv444p" : " or use --codec prores4444"));
}

}  // namespace

std::optional<Container> containerFromName(const std::filesystem::path& path) {
  const std::string extension = lowercase(path.extension().string());
  for (const Container container : {Container::Mp4, Container::Mov, Container::Mkv})
    if (extension == extensionOf(container)) return container;
  return std::nullopt;
}

bool isFilmName(const std::filesystem::path& path) { return containerFromName(path).has_value(); }

std::string otherMediaExtension(const std::filesystem::path& path) {
  static constexpr std::string_view kOthers[] = {
      ".mp3", ".wav", ".flac", ".ogg", ".oga", ".opus", ".aac", ".m4a", ".wma", ".aif", ".aiff",        // sound
      ".avi", ".webm", ".wmv", ".flv", ".mpg", ".mpeg", ".m4v", ".ogv", ".ts", ".mts", ".m2ts", ".3gp",  // film
      ".gif", ".exr", ".png", ".jpg", ".jpeg", ".tif", ".tiff", ".webp"};                               // picture
  const std::string extension = lowercase(path.extension().string());
  for (const std::string_view other : kOthers)
    if (extension == other) return extension;
  return {};
}

std::string_view codecName(Codec codec) {
  for (const auto& [c, name] : kCodecs)
    if (c == codec) return name;
  return "";
}

Codec parseCodec(std::string_view text) {
  const std::string name = lowercase(std::string(text));
  for (const auto& [codec, codecText] : kCodecs)
    if (name == codecText) return codec;
  throw Error(fmt::format("--codec takes h264, hevc, prores, prores4444 or ffv1, not '{}'.", text));
}

int64_t parseBitrate(std::string_view text) {
  std::string_view digits = text;
  double scale = 1.0;
  if (digits.ends_with('k') || digits.ends_with('K')) scale = 1e3, digits.remove_suffix(1);
  else if (digits.ends_with('M')) scale = 1e6, digits.remove_suffix(1);
  double value = 0.0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const double bits = value * scale;
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size() || !(bits >= 1000.0) ||
      !(bits <= double(kMaxBitrate)))
    throw Error(fmt::format("--bitrate expects bits a second from 1k to 1000M, as 8M, 2500k or 1.5M, not '{}'.", text));
  return int64_t(std::llround(bits));
}

FilmFormat resolveFilm(const std::filesystem::path& target, const FilmRequest& request, uint32_t width,
                       uint32_t height) {
  const std::optional<Container> container = containerFromName(target);
  if (!container)
    throw Error(fmt::format("A film is written as .mp4, .mov or .mkv, not '{}'.", target.string()));
  FilmFormat format;
  format.container = *container;
  format.codec = request.codec.value_or(defaultCodec(*container));
  const std::string_view codec = codecName(format.codec);
  if (!holds(format.container, format.codec))
    throw Error(fmt::format("A {} film holds {}, not {}; name it {} for {}.", extensionOf(format.container),
                            heldList(format.container), codec, homeOf(format.codec), codec));
  format.muxer = format.container == Container::Mp4 ? "mp4" : format.container == Container::Mov ? "mov" : "matroska";

  if (request.crf && request.bitrate) throw Error("--crf and --bitrate both set the quality: give one of them.");
  if (!isDelivery(format.codec)) {
    const std::string_view why = format.codec == Codec::Ffv1 ? "it is lossless" : "its quality is its profile's";
    if (request.crf) throw Error(fmt::format("--crf is for h264 and hevc, not {}: {}.", codec, why));
    if (request.bitrate) throw Error(fmt::format("--bitrate is for h264 and hevc, not {}: {}.", codec, why));
    if (!request.preset.empty()) throw Error(fmt::format("--encoder-preset is for h264 and hevc, not {}: {}.", codec, why));
    if (!request.pixelFormat.empty())
      throw Error(fmt::format("--pix-fmt is for h264 and hevc; {} is always {}.", codec,
                              format.codec == Codec::Prores       ? "yuv422p10le (ProRes 422 HQ)"
                              : format.codec == Codec::Prores4444 ? "yuv444p10le (ProRes 4444)"
                                                                  : "8-bit RGB (bgr0), lossless"));
  }

  switch (format.codec) {
    case Codec::H264:
    case Codec::Hevc: {
      format.encoder = format.codec == Codec::H264 ? "libx264" : "libx265";
      format.pixelFormat = request.pixelFormat.empty() ? "yuv420p" : lowercase(request.pixelFormat);
      if (std::find(kYuvFormats.begin(), kYuvFormats.end(), format.pixelFormat) == kYuvFormats.end())
        throw Error(fmt::format("--pix-fmt for {} takes yuv420p, yuv444p, yuv420p10le or yuv444p10le, not '{}'.",
                                codec, request.pixelFormat));
      if (request.bitrate) format.bitrate = request.bitrate;
      else format.crf = request.crf.value_or(format.codec == Codec::H264 ? 18 : 20);
      format.preset = request.preset.empty() ? "medium" : lowercase(request.preset);
      if (std::find(kEncoderPresets.begin(), kEncoderPresets.end(), format.preset) == kEncoderPresets.end())
        throw Error(fmt::format("--encoder-preset takes {}, not '{}'.", fmt::join(kEncoderPresets, ", "), request.preset));
      format.audioEncoder = "aac";
      break;
    }
    case Codec::Prores:
    case Codec::Prores4444:
      format.encoder = "prores_ks";
      format.pixelFormat = format.codec == Codec::Prores ? "yuv422p10le" : "yuv444p10le";
      format.proresProfile = format.codec == Codec::Prores ? "hq" : "4444";
      format.audioEncoder = "pcm_s24le";
      break;
    case Codec::Ffv1:
      // 8-bit RGB, stored losslessly: the PNG frame's bytes come back exactly. FFmpeg 5.1's FFV1 takes
      // 8-bit RGB as bgr0 only (planar gbrp starts at 9 bits).
      format.encoder = "ffv1";
      format.pixelFormat = "bgr0";
      format.rgb = true;
      format.audioEncoder = "pcm_s24le";
      break;
  }
  format.deep = format.pixelFormat.find("10le") != std::string::npos;
  format.fullRange = format.rgb || request.fullRange;  // RGB is always full range
  checkSubsampling(format.pixelFormat, width, height);
  return format;
}

DisplayLayout displayLayout(const FilmFormat& format) {
  if (format.deep) return DisplayLayout::Rgb48;
  return format.rgb ? DisplayLayout::Bgr0 : DisplayLayout::Rgb24;
}

uint32_t bytesPerPixel(DisplayLayout layout) {
  switch (layout) {
    case DisplayLayout::Rgb24: return 3;
    case DisplayLayout::Bgr0:
    case DisplayLayout::Rgb0: return 4;
    case DisplayLayout::Rgb48: return 6;
  }
  return 0;
}

}  // namespace vitrine::film
