#pragma once
// The frame's colours as light signals: the mean colour of each region of a grid, and the dominant
// colours (a small k-means). Both work on a small linear image the host reduced the frame to (the
// gallery's readback, or a headless run's last frame), on the lights thread, never the frame thread.
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace vitrine {
struct ImageRgba;
}

namespace vitrine::lights {

// A frame reduced to a few thousand pixels, linear RGB, top row first.
struct SmallFrame {
  uint32_t width = 0, height = 0;
  std::vector<glm::vec3> pixels;
};

// The frame reduced to at most kRegionWidth x kRegionHeight, each pixel the mean of the frame's pixels
// whose centres fall in it (colours clamped to 0..1 first, as a display shows them): what the regions
// are measured over. The dominant colours are found over a further reduction to kSmallWidth x kSmallHeight.
inline constexpr uint32_t kRegionWidth = 256, kRegionHeight = 144;
inline constexpr uint32_t kSmallWidth = 64, kSmallHeight = 36;
SmallFrame reduceImage(const ImageRgba& image);
// The same from 8-bit sRGB RGBA rows (a readback of the shown frame), `stride` bytes apart.
SmallFrame reduceSrgb8(const uint8_t* bytes, uint32_t width, uint32_t height, uint32_t stride);
// A small frame reduced further, to at most width x height.
SmallFrame shrink(const SmallFrame& frame, uint32_t width, uint32_t height);

// The mean colour of each of `across` x `down` regions, row after row (a region's pixels are those whose
// centres fall in it; a grid finer than the frame repeats the nearest pixel).
std::vector<glm::vec3> regionMeans(const SmallFrame& frame, int across, int down);

struct ColourCluster {
  glm::vec3 colour{0.0f};
  float share = 0.0f;  // of the frame's pixels
};
// The `k` dominant colours, most of the frame first: k-means in linear RGB seeded by farthest points
// (deterministic: the same frame gives the same colours), at most `iterations` rounds. Fewer than k
// when the frame has fewer distinct colours.
std::vector<ColourCluster> dominantColours(const SmallFrame& frame, size_t k, int iterations = 8);

}  // namespace vitrine::lights
