#include "image/image.h"

#include <Imath/half.h>

#include <cmath>

namespace vitrine {

ImageRgba imageFromHalves(uint32_t width, uint32_t height, std::span<const uint16_t> halves) {
  ImageRgba image{width, height, std::vector<float>(size_t(width) * height * 4)};
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    half h;
    h.setBits(halves[i]);
    image.pixels[i] = float(h);
  }
  return image;
}

float linearToSrgb(float linear) {
  if (!(linear > 0.0f)) return 0.0f;
  if (linear >= 1.0f) return 1.0f;
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgbToLinear(float encoded) {
  if (!(encoded > 0.0f)) return 0.0f;
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace vitrine
