#pragma once
// What an image file holds, judged by its first bytes rather than its name, and the check every
// image reader makes before a decoder sees the file: a decoder handed /dev/zero never returns, and
// one handed a PNG named .exr reports something about magic numbers.
#include <filesystem>
#include <span>
#include <string_view>

namespace vitrine {

// "EXR", "PNG", "JPEG", "TIFF", "Radiance HDR", "GIF", "WebP", "BMP" from a file's first bytes (16
// are enough); empty when none of them.
std::string_view sniffImageFormat(std::span<const unsigned char> head);

// Throws vitrine::Error naming the path unless it is a regular file whose bytes begin like an EXR and
// whose header OpenEXR's C core reads whole (checkExrHeader).
void checkExrFile(const std::filesystem::path& path);

// The largest EXR side Vitrine reads (a panorama, a backdrop, a golden frame).
constexpr int kMaxExrSide = 16384;

// Throws vitrine::Error naming the path and what is wrong unless OpenEXR's C core (OpenEXRCore,
// exr_start_read with strict header checks) parses the whole header of the EXR file at `path`: every
// attribute inside the file, sizes and windows consistent, at most kMaxExrSide pixels a side. It reads
// the header only, in well under a millisecond, and runs before OpenImageIO or OpenEXR's C++ library
// see the file: the C++ library trusts an attribute's declared size and allocated and cleared 1.7 GB
// for an 857-byte file (fuzz/image_exr; tests/fuzz-regressions/image_exr/huge-attribute-*).
void checkExrHeader(const std::filesystem::path& path);

// True when `path` is a regular file whose first bytes are the EXR magic number (whatever its name).
bool startsLikeExr(const std::filesystem::path& path);

// Throws vitrine::Error naming the path unless every chunk of the PNG at `path` before its image data
// fits in the file: OpenImageIO's PNG reader trusted a 498-byte file's text chunk claiming 1.3 GB and
// spent 18 s on it (fuzz/image_png; tests/fuzz-regressions/image_png/huge-text-chunk-*). Reads the
// chunk headers only. A file that is not a PNG passes.
void checkPngChunks(const std::filesystem::path& path);

// What every reader runs before a decoder sees a file, whatever its name: checkExrHeader for an EXR,
// checkPngChunks for a PNG.
void checkImageHeader(const std::filesystem::path& path);

}  // namespace vitrine
