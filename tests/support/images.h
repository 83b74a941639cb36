#pragma once
// Images the image tests build by hand.
#include "image/image.h"

#include <cstdint>
#include <vector>

namespace vitrine::test {

// w x h pixels whose every channel is v.
inline ImageRgba flatImage(uint32_t w, uint32_t h, float v) { return {w, h, std::vector<float>(size_t(w) * h * 4, v)}; }

}  // namespace vitrine::test
