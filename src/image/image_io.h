#pragma once
// The one module that touches image files: EXR through OpenEXR, PNG through libpng, JPEG through
// libjpeg; pictures in other formats through OpenImageIO, a module loaded on the first such picture
// (none with VITRINE_WITH_OIIO=OFF, the packed GPU-machine binary).
#include "image/image.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vitrine {

// Text attributes for a written file's header (EXR) or text chunks (PNG): name, value.
using ImageNotes = std::vector<std::pair<std::string, std::string>>;

enum class ImageFormat { Exr, Png };
// The format a file's name asks for, decided here only: its extension in any case (".exr", ".Png");
// nothing for any other name. Options, headless runs and the writers all ask this.
std::optional<ImageFormat> imageFormatFromName(const std::filesystem::path& path);

// Writes linear half-float EXR, or 8-bit sRGB PNG when imageFormatFromName says PNG: encoded in
// memory, then written through a temporary file, every byte checked on disk before it is renamed into
// place (writeFileAtomically), so a reader never sees half a file and a full disk is an error with
// the system's reason, the old file left as it was. Throws vitrine::Error.
void writeImage(const std::filesystem::path& path, const ImageRgba& image, const ImageNotes& notes = {});
// The display values writeImage puts in a PNG, without the file: sRGB-encoded (IEC 61966-2-1), clamped
// to [0, 1], RGBA, top row first, at 8 bits (`srgb8`, the PNG's very bytes) or on the same curve at 16
// bits (`srgb16`, for 10-bit films). A film's frames are made from these, so a frame equals its PNG.
std::vector<uint8_t> srgb8(const ImageRgba& image);
std::vector<uint16_t> srgb16(const ImageRgba& image);
// True when `path` decodes whole as an image of width x height (a frame a resumed recording may keep):
// false for a truncated, corrupt or differently sized file, or one this build cannot read.
bool isWholeImage(const std::filesystem::path& path, uint32_t width, uint32_t height);
// Reads an EXR (RGBA, any pixel type) into linear floats. Throws vitrine::Error, naming the path, for
// anything but a regular file that starts like an EXR (a device, a folder, a PNG named .exr).
ImageRgba readImage(const std::filesystem::path& path);

// A picture for display (a photo, a wallpaper): 8-bit RGBA, sRGB-encoded, top row first.
struct Picture {
  uint32_t width = 0, height = 0;
  std::vector<uint8_t> rgba;
};
// Reads any format the image library knows (JPEG, PNG, WebP, TIFF, EXR, ...) scaled down, keeping its
// aspect, so that neither side exceeds maxSide; grey and RGB gain opaque alpha. Throws vitrine::Error
// naming the path and the reason (the build without OpenImageIO's module reads PNG, JPEG and EXR only).
Picture readPicture(const std::filesystem::path& path, uint32_t maxSide);
// The largest picture file read (a photo, a panorama): a 16384x8192 EXR of half RGBA, uncompressed.
inline constexpr uintmax_t kMaxPictureFileBytes = uintmax_t(1) << 30;

}  // namespace vitrine
