#include "lights/dmx_sources.h"

#include "live/source_bank.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>

namespace vitrine::lights {

void DmxSources::apply(uint32_t universe, const Universe& channels, live::SourceBank& sources) {
  const auto [held, first] = held_.try_emplace(universe, Universe{});
  Universe& before = held->second;
  for (int c = 0; c < kUniverseChannels; ++c) {
    if (channels[size_t(c)] == before[size_t(c)]) continue;
    sources.set(fmt::format("dmx.{}.{}", universe, c + 1), float(channels[size_t(c)]) / 255.0f);
    // The pairs this channel is in: as the coarse half (C, C+1) and as the fine half (C-1, C).
    if (c + 1 < kUniverseChannels)
      sources.set(fmt::format("dmx16.{}.{}", universe, c + 1), pairLevel(channels[size_t(c)], channels[size_t(c) + 1]));
    if (c > 0) sources.set(fmt::format("dmx16.{}.{}", universe, c), pairLevel(channels[size_t(c) - 1], channels[size_t(c)]));
  }
  before = channels;
}

std::vector<uint32_t> universesRead(const std::vector<std::string>& sourceNames) {
  std::vector<uint32_t> universes;
  for (const std::string& name : sourceNames) {
    const size_t dot = name.find('.');
    if (dot == std::string::npos || (name.compare(0, dot, "dmx") != 0 && name.compare(0, dot, "dmx16") != 0)) continue;
    uint32_t universe = 0;
    const char* begin = name.data() + dot + 1;
    const char* end = name.data() + name.size();
    const auto [stop, ec] = std::from_chars(begin, end, universe);
    if (ec != std::errc() || stop == end || *stop != '.') continue;
    if (std::find(universes.begin(), universes.end(), universe) == universes.end()) universes.push_back(universe);
  }
  return universes;
}

}  // namespace vitrine::lights
