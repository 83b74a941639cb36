#pragma once
// A linear RGBA float image on the CPU: what read-backs produce, EXR files hold and goldens compare.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace vitrine {

struct ImageRgba {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<float> pixels;  // width * height * 4, row-major, top row first

  float* at(uint32_t x, uint32_t y) { return &pixels[(size_t(y) * width + x) * 4]; }
  const float* at(uint32_t x, uint32_t y) const { return &pixels[(size_t(y) * width + x) * 4]; }
};

// rgba16f texels as the GPU lays them out (a read-back of an HDR image) into linear floats.
ImageRgba imageFromHalves(uint32_t width, uint32_t height, std::span<const uint16_t> halves);

// sRGB transfer functions (IEC 61966-2-1), for PNG output and for shaders that think in display values.
float linearToSrgb(float linear);
float srgbToLinear(float encoded);

}  // namespace vitrine
