#pragma once
// Which monitor shows a window: the one whose area shares the most of the window's, as a window
// manager places a window that spans two. Pure, for tests/unit/screen_area_test.cpp; window.cpp
// asks GLFW for the areas.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>

namespace vitrine::host {

struct ScreenArea {  // desktop pixels
  int x = 0, y = 0, width = 0, height = 0;
};

inline int64_t sharedPixels(const ScreenArea& a, const ScreenArea& b) {
  const int64_t width = std::min(int64_t(a.x) + a.width, int64_t(b.x) + b.width) - std::max(a.x, b.x);
  const int64_t height = std::min(int64_t(a.y) + a.height, int64_t(b.y) + b.height) - std::max(a.y, b.y);
  return width > 0 && height > 0 ? width * height : 0;
}

// The index of the area that shares the most pixels with `window` (the first of equals); none when
// the window lies off every one.
inline std::optional<size_t> mostShared(const ScreenArea& window, std::span<const ScreenArea> areas) {
  std::optional<size_t> best;
  int64_t most = 0;
  for (size_t i = 0; i < areas.size(); ++i)
    if (const int64_t shared = sharedPixels(window, areas[i]); shared > most) most = shared, best = i;
  return best;
}

}  // namespace vitrine::host
