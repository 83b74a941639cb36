#pragma once
// Headless neon frames for the neon GPU tests (neon_scene_test.cpp, neon_tubes_test.cpp): a run of
// the scene on small frames, its picture read back, and where the tubes changed it.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "host/input_script.h"
#include "host/offline/offscreen.h"
#include "image/image.h"

namespace vitrine::test::neon_frames {

struct Render {
  VkExtent2D size{240, 135};
  double step = 1.0 / 60.0;
  double seconds = 1.0;  // simulated
  params::KeyValues values;
  const char* script = nullptr;
  std::vector<std::string> presets;  // applied before the values
};

inline host::OffscreenConfig neonConfig(const Render& r) {
  host::OffscreenConfig c;
  c.scene = "neon";
  c.size = r.size;
  c.step = r.step;
  c.presets = r.presets;
  c.parameters = r.values;
  if (r.script) c.input = host::parseInputScript(r.script, "test script");
  return c;
}

inline ImageRgba neonRender(const gpu::Device& device, const Render& r) {
  host::Offscreen offscreen(device, neonConfig(r));
  const int frames = int(std::lround(r.seconds / r.step));
  for (int i = 0; i < frames; ++i) offscreen.renderFrame(1, i + 1 == frames);  // the last one drawn: it is read
  return offscreen.readback();
}

// The frame as a viewer sees it: sRGB-encoded display values.
inline ImageRgba display(ImageRgba image) {
  for (size_t i = 0; i < image.pixels.size(); ++i)
    if (i % 4 != 3) image.pixels[i] = linearToSrgb(std::clamp(image.pixels[i], 0.0f, 1.0f));
  return image;
}

// Where the tubes changed `frame` from `facade` (the same frame without tubes, stage base) by more than
// 0.1 in some channel.
inline std::vector<bool> tubeMask(const ImageRgba& frame, const ImageRgba& facade) {
  std::vector<bool> mask(size_t(frame.width) * frame.height);
  for (size_t i = 0; i < mask.size(); ++i) {
    const float* p = &frame.pixels[i * 4];
    const float* q = &facade.pixels[i * 4];
    mask[i] = std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])}) >= 0.1f;
  }
  return mask;
}

inline float maxChannel(const float* p) { return std::max({p[0], p[1], p[2]}); }
inline float minChannel(const float* p) { return std::min({p[0], p[1], p[2]}); }

}  // namespace vitrine::test::neon_frames
