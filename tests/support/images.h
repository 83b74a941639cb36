#pragma once
// Images the image tests build by hand, and a measure of pictures the tier tests share.
#include "image/image.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace vitrine::test {

// w x h pixels whose every channel is v.
inline ImageRgba flatImage(uint32_t w, uint32_t h, float v) { return {w, h, std::vector<float>(size_t(w) * h * 4, v)}; }

// The picture seen from a few steps back: the mean luminance of each 8 x 8 block. A lower tier
// renders fewer pixels and upscales them, which softens edges but moves no light between blocks;
// a strand not drawn, a march cut short or vapour lost does.
inline std::vector<double> blockLuminance(const ImageRgba& image) {
  std::vector<double> blocks;
  for (uint32_t by = 0; by + 8 <= image.height; by += 8)
    for (uint32_t bx = 0; bx + 8 <= image.width; bx += 8) {
      double sum = 0.0;
      for (uint32_t y = by; y < by + 8; ++y)
        for (uint32_t x = bx; x < bx + 8; ++x) {
          const float* p = image.at(int(x), int(y));
          sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        }
      blocks.push_back(sum / 64.0);
    }
  return blocks;
}

// How far b's blocks are from a's, as a share of a's light.
inline double blockError(const std::vector<double>& a, const std::vector<double>& b) {
  double difference = 0.0, total = 0.0;
  for (size_t i = 0; i < a.size(); ++i) difference += std::abs(a[i] - b[i]), total += a[i];
  return difference / total;
}
inline double blockError(const ImageRgba& a, const ImageRgba& b) { return blockError(blockLuminance(a), blockLuminance(b)); }

}  // namespace vitrine::test
