#include "lights/frame_colours.h"

#include "image/image.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vitrine::lights {

namespace {

template <class Pixel> SmallFrame reduce(uint32_t width, uint32_t height, uint32_t maxWidth, uint32_t maxHeight, Pixel pixel) {
  SmallFrame small;
  if (width == 0 || height == 0) return small;
  small.width = std::min(width, maxWidth);
  small.height = std::min(height, maxHeight);
  small.pixels.assign(size_t(small.width) * small.height, glm::vec3(0.0f));
  std::vector<uint32_t> counts(small.pixels.size(), 0);
  for (uint32_t y = 0; y < height; ++y) {
    const size_t sy = size_t((uint64_t(y) * 2 + 1) * small.height / (uint64_t(height) * 2));
    for (uint32_t x = 0; x < width; ++x) {
      const size_t sx = size_t((uint64_t(x) * 2 + 1) * small.width / (uint64_t(width) * 2));
      small.pixels[sy * small.width + sx] += glm::clamp(pixel(x, y), glm::vec3(0.0f), glm::vec3(1.0f));
      ++counts[sy * small.width + sx];
    }
  }
  for (size_t i = 0; i < small.pixels.size(); ++i)
    if (counts[i] > 0) small.pixels[i] /= float(counts[i]);
  return small;
}

}  // namespace

SmallFrame reduceImage(const ImageRgba& image) {
  return reduce(image.width, image.height, kRegionWidth, kRegionHeight, [&](uint32_t x, uint32_t y) {
    const float* p = image.at(x, y);
    return glm::vec3(std::isfinite(p[0]) ? p[0] : 0.0f, std::isfinite(p[1]) ? p[1] : 0.0f, std::isfinite(p[2]) ? p[2] : 0.0f);
  });
}

SmallFrame reduceSrgb8(const uint8_t* bytes, uint32_t width, uint32_t height, uint32_t stride) {
  std::array<float, 256> linear;
  for (size_t i = 0; i < linear.size(); ++i) linear[i] = srgbToLinear(float(i) / 255.0f);
  return reduce(width, height, kRegionWidth, kRegionHeight, [&](uint32_t x, uint32_t y) {
    const uint8_t* p = bytes + size_t(y) * stride + size_t(x) * 4;
    return glm::vec3(linear[p[0]], linear[p[1]], linear[p[2]]);
  });
}

SmallFrame shrink(const SmallFrame& frame, uint32_t width, uint32_t height) {
  if (frame.width <= width && frame.height <= height) return frame;
  return reduce(frame.width, frame.height, width, height,
                [&](uint32_t x, uint32_t y) { return frame.pixels[size_t(y) * frame.width + x]; });
}

std::vector<glm::vec3> regionMeans(const SmallFrame& frame, int across, int down) {
  std::vector<glm::vec3> means(size_t(std::max(across, 0)) * size_t(std::max(down, 0)), glm::vec3(0.0f));
  if (frame.width == 0 || frame.height == 0 || means.empty()) return means;
  std::vector<uint32_t> counts(means.size(), 0);
  for (uint32_t y = 0; y < frame.height; ++y)
    for (uint32_t x = 0; x < frame.width; ++x) {
      const size_t gx = size_t((uint64_t(x) * 2 + 1) * uint64_t(across) / (uint64_t(frame.width) * 2));
      const size_t gy = size_t((uint64_t(y) * 2 + 1) * uint64_t(down) / (uint64_t(frame.height) * 2));
      const size_t cell = gy * size_t(across) + gx;
      means[cell] += frame.pixels[size_t(y) * frame.width + x];
      ++counts[cell];
    }
  for (int gy = 0; gy < down; ++gy)
    for (int gx = 0; gx < across; ++gx) {
      const size_t cell = size_t(gy) * size_t(across) + size_t(gx);
      if (counts[cell] > 0) {
        means[cell] /= float(counts[cell]);
        continue;
      }
      // Finer than the frame: the pixel under the region's centre.
      const auto x = uint32_t(std::min<double>((gx + 0.5) * frame.width / across, frame.width - 1));
      const auto y = uint32_t(std::min<double>((gy + 0.5) * frame.height / down, frame.height - 1));
      means[cell] = frame.pixels[size_t(y) * frame.width + x];
    }
  return means;
}

std::vector<ColourCluster> dominantColours(const SmallFrame& frame, size_t k, int iterations) {
  const std::vector<glm::vec3>& pixels = frame.pixels;
  if (pixels.empty() || k == 0) return {};
  // Seeds by farthest points: the pixel farthest from the frame's mean, then each time the pixel farthest
  // from every seed so far, so well-separated colours each get one (deterministic, unlike k-means++).
  const auto distance2 = [](glm::vec3 a, glm::vec3 b) { return glm::dot(a - b, a - b); };
  glm::vec3 mean(0.0f);
  for (const glm::vec3& p : pixels) mean += p;
  mean /= float(pixels.size());
  const auto farthest = [&](const std::vector<float>& d) { return size_t(std::max_element(d.begin(), d.end()) - d.begin()); };
  std::vector<float> nearest(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) nearest[i] = distance2(pixels[i], mean);
  std::vector<glm::vec3> centres{pixels[farthest(nearest)]};
  for (size_t i = 0; i < pixels.size(); ++i) nearest[i] = distance2(pixels[i], centres[0]);
  while (centres.size() < k) {
    const size_t next = farthest(nearest);
    if (!(nearest[next] > 0.0f)) break;  // every pixel is a seed's colour already
    centres.push_back(pixels[next]);
    for (size_t i = 0; i < pixels.size(); ++i) nearest[i] = std::min(nearest[i], distance2(pixels[i], pixels[next]));
  }
  std::vector<size_t> members(centres.size());
  std::vector<glm::vec3> sums(centres.size());
  for (int round = 0; round < std::max(iterations, 1); ++round) {
    std::fill(members.begin(), members.end(), 0);
    std::fill(sums.begin(), sums.end(), glm::vec3(0.0f));
    for (const glm::vec3& p : pixels) {
      size_t best = 0;
      float closest = std::numeric_limits<float>::max();
      for (size_t c = 0; c < centres.size(); ++c)
        if (const float d = distance2(p, centres[c]); d < closest) closest = d, best = c;
      sums[best] += p;
      ++members[best];
    }
    bool moved = false;
    for (size_t c = 0; c < centres.size(); ++c) {
      if (members[c] == 0) continue;
      const glm::vec3 centre = sums[c] / float(members[c]);
      moved = moved || centre != centres[c];
      centres[c] = centre;
    }
    if (!moved) break;
  }
  std::vector<ColourCluster> clusters;
  for (size_t c = 0; c < centres.size(); ++c)
    if (members[c] > 0) clusters.push_back({centres[c], float(members[c]) / float(pixels.size())});
  std::stable_sort(clusters.begin(), clusters.end(), [](const ColourCluster& a, const ColourCluster& b) { return a.share > b.share; });
  return clusters;
}

}  // namespace vitrine::lights
