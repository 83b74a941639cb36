#include "lights/fixtures.h"

#include "host/flash_guard_math.h"

#include <algorithm>
#include <cmath>

namespace vitrine::lights {

uint8_t dmxLevel(float level) {
  if (!(level > 0.0f)) return 0;
  return uint8_t(std::lround(std::min(level, 1.0f) * 255.0f));
}

float pairLevel(uint8_t coarse, uint8_t fine) { return float(unsigned(coarse) * 256u + fine) / 65535.0f; }

std::array<uint8_t, 2> levelPair(float level) {
  const auto value = unsigned(std::lround(std::clamp(std::isfinite(level) ? level : 0.0f, 0.0f, 1.0f) * 65535.0f));
  return {uint8_t(value >> 8), uint8_t(value & 0xff)};
}

std::vector<glm::vec3> lightColours(const Patch& patch, const Signals& signals, float master) {
  std::vector<glm::vec3> colours;
  master = std::clamp(std::isfinite(master) ? master : 0.0f, 0.0f, 1.0f);
  for (const Fixture& fixture : patch.fixtures) {
    const std::vector<glm::vec3>* signal = signals.find(fixture.signal);
    const int n = lights(fixture);
    const size_t first = size_t(fixture.index);
    const size_t available = signal && signal->size() > first ? signal->size() - first : 0;
    for (int i = 0; i < n; ++i) {
      if (available == 0) {
        colours.emplace_back(0.0f);
        continue;
      }
      // A strip spreads the colours it is given over its pixels; a single light takes the first.
      const size_t at = first + std::min(available - 1, size_t(i) * available / size_t(n));
      colours.push_back((*signal)[at] * master);
    }
  }
  return colours;
}

Universes pack(const Patch& patch, const std::vector<glm::vec3>& colours) {
  Universes universes;
  size_t light = 0;
  for (const Fixture& fixture : patch.fixtures) {
    Universe& dmx = universes.try_emplace(fixture.universe, Universe{}).first->second;
    uint8_t* out = dmx.data() + (fixture.address - 1);
    for (int i = 0; i < lights(fixture); ++i, ++light) {
      const glm::vec3 c = light < colours.size() ? colours[light] : glm::vec3(0.0f);
      switch (fixture.type) {
        case FixtureType::Rgb:
        case FixtureType::Pixels:
          for (int k = 0; k < 3; ++k) *out++ = dmxLevel(c[k]);
          break;
        case FixtureType::Rgbw: {
          const float white = std::min({c.r, c.g, c.b});
          for (int k = 0; k < 3; ++k) *out++ = dmxLevel(c[k] - white);
          *out++ = dmxLevel(white);
          break;
        }
        case FixtureType::Dimmer: *out++ = dmxLevel(host::flash::luminance(c)); break;
      }
    }
  }
  return universes;
}

}  // namespace vitrine::lights
