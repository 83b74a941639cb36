#pragma once
// The image readers as Vitrine calls them, for the image fuzz targets: each writes the input to a file
// named `name` (the extension picks OpenImageIO's reader first), reads it, and checks what came back.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace vitrine::fuzz {

void readAsPanorama(std::string_view name, const uint8_t* data, size_t size);  // readImage
void readAsBackdrop(std::string_view name, const uint8_t* data, size_t size);  // readPicture, 2048 a side
}  // namespace vitrine::fuzz
