#pragma once
// How bright the neon tubes are and how wide they are drawn, in plain C++: the CPU picks the values,
// shaders/neon/tube.vert and tube.frag use them (through NeonFrame).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vitrine::neon {

// The tubes' light is additive, so a frame with many tubes alive would add up to a white glare; an
// energy budget scales every tube's emission by tubeExposure(alive): 1 up to kBudgetTubes tubes, then
// falling as alive^-kBudgetFalloff, so the frame's total tube light still grows with the count (more
// tubes read as more) but only as alive^(1 - kBudgetFalloff), and overlaps stay coloured.
inline constexpr float kBudgetTubes = 24.0f;
inline constexpr float kBudgetFalloff = 0.9f;

inline float tubeExposure(uint32_t alive) {
  const float n = float(alive);
  return n <= kBudgetTubes ? 1.0f : std::pow(kBudgetTubes / n, kBudgetFalloff);
}

// The thinnest a tube is drawn, in pixels of radius: a far tube on a small frame (480x270) would
// otherwise be a ribbon a pixel wide that rasterises into stripes. A tube narrower than this on screen
// is widened to it, so it stays a continuous, round line at every size.
inline constexpr float kMinTubeRadiusPixels = 1.3f;

// A tube's radius on screen, in pixels: `radius` metres at `depth` metres along the view, for a frame
// `frameHeight` pixels tall seen through a vertical field of view `fovY`.
inline float tubeRadiusPixels(float radius, float depth, float frameHeight, float fovY) {
  return radius * (0.5f * frameHeight / std::tan(0.5f * fovY)) / depth;
}

// The radius drawn (metres): widened to kMinTubeRadiusPixels where the true one is thinner.
inline float drawnTubeRadius(float radius, float depth, float frameHeight, float fovY) {
  const float pixels = tubeRadiusPixels(radius, depth, frameHeight, fovY);
  return pixels >= kMinTubeRadiusPixels ? radius : radius * kMinTubeRadiusPixels / std::max(pixels, 1e-6f);
}

// Which of the three neon colours the release with this serial glows in: one step round the three
// from each release to the next, two steps every third, so consecutive releases never share a colour
// and an autopilot whose pens take turns gives each pen every colour in turn. Mirrored by tube.vert.
inline uint32_t tubeColour(uint32_t serial) { return (serial + serial / 3u) % 3u; }

}  // namespace vitrine::neon
