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

// Throws vitrine::Error naming the path unless it is a regular file whose bytes begin like an EXR.
void checkExrFile(const std::filesystem::path& path);

}  // namespace vitrine
