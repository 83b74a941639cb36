#include "support/image_input.h"

#include "core/error.h"
#include "image/image_io.h"
#include "support/temp_file.h"

#include "support/require.h"

namespace vitrine::fuzz {
namespace {

constexpr uint32_t kBackdropSide = 2048;  // glass_scene.cpp's kMaxPictureSide

}  // namespace

void readAsPanorama(std::string_view name, const uint8_t* data, size_t size) {
  try {
    const ImageRgba image = readImage(writeTempFile(name, data, size));
    require(image.pixels.size() == size_t(image.width) * image.height * 4, "readImage: pixels do not match its size");
  } catch (const Error&) {
  }
}

void readAsBackdrop(std::string_view name, const uint8_t* data, size_t size) {
  try {
    const Picture picture = readPicture(writeTempFile(name, data, size), kBackdropSide);
    require(picture.width > 0 && picture.height > 0 && picture.width <= kBackdropSide &&
                picture.height <= kBackdropSide,
            "readPicture: a size outside 1..maxSide");
    require(picture.rgba.size() == size_t(picture.width) * picture.height * 4, "readPicture: pixels do not match its size");
  } catch (const Error&) {
  }
}

}  // namespace vitrine::fuzz
