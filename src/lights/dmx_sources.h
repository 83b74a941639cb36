#pragma once
// DMX in as live sources (docs/LIVE.md): channel C of universe U reads `dmx.U.C` (C from 1, value/255),
// and the 16-bit pair of channels C (coarse) and C+1 (fine) reads `dmx16.U.C` ((coarse*256+fine)/65535),
// as a lighting desk sends a fine fader or a moving head's pan. Only channels that change are written,
// so a universe of faders at rest costs nothing and names only what moved.
#include "lights/fixtures.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace vitrine::live {
class SourceBank;
}

namespace vitrine::lights {

class DmxSources {
 public:
  // Writes the sources of the channels of `universe` that differ from what it held before (all of its
  // non-zero channels the first time).
  void apply(uint32_t universe, const Universe& channels, live::SourceBank& sources);

 private:
  std::map<uint32_t, Universe> held_;
};

// The universes a set of source names reads (dmx.U.C, dmx16.U.C), each once, in order.
std::vector<uint32_t> universesRead(const std::vector<std::string>& sourceNames);

}  // namespace vitrine::lights
