#pragma once
// The lights' patch (--lights FILE, or the settings file's "lights"): which light signals drive which
// fixtures on which DMX universes and addresses, the region grid the frame is measured over, the
// universes a lighting desk's faders come in on, and olad's port. docs/LIGHTS.md has the format.
//
//   {"grid": [8, 1], "master": 1, "master_source": "dmx.1.512", "blackout_source": "osc.blackout",
//    "input": [1], "olad": 9010,
//    "fixtures": [{"name": "wall", "type": "pixels", "count": 8, "universe": 0, "address": 1, "signal": "regions"},
//                 {"name": "crystal", "type": "rgb", "universe": 0, "address": 25, "signal": "bloom.phase"}]}
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::lights {

enum class FixtureType { Rgb, Rgbw, Dimmer, Pixels };

inline constexpr int kUniverseChannels = 512;
inline constexpr uint32_t kMaxUniverse = 65535;
inline constexpr int kMaxPixels = 170;          // 510 channels: a strip fits one universe
inline constexpr size_t kMaxFixtures = 1024;
inline constexpr int kMaxGridSide = 64;
inline constexpr uintmax_t kMaxPatchBytes = 1 << 20;

struct Fixture {
  std::string name;
  FixtureType type = FixtureType::Rgb;
  uint32_t universe = 0;
  int address = 1;      // the first channel, 1..512
  int count = 1;        // pixels of a strip; 1 for the others
  std::string signal;   // a name of kSignalNames
  int index = 0;        // the signal's first colour this fixture shows (a region, a dominant colour)
  int line = 0;         // where the file declares it, for messages
  bool operator==(const Fixture&) const = default;
};

// The channels a fixture takes: 3 an RGB light or pixel, 4 RGBW, 1 a dimmer.
int channels(const Fixture& fixture);
// The lights a fixture shows: `count` pixels of a strip, else one.
inline int lights(const Fixture& fixture) { return fixture.type == FixtureType::Pixels ? fixture.count : 1; }

struct Patch {
  int gridWidth = 8, gridHeight = 1;  // the regions the frame is measured over
  float master = 1.0f;                // the master dimmer's value at start, 0..1
  std::string masterSource;           // a live source that moves the master (dmx.1.512, midi.cc.1.7, osc.master)
  std::string blackoutSource;         // a live source that blacks out above one half (osc.blackout)
  std::vector<uint32_t> input;        // universes whose channels are the dmx.* sources
  uint16_t oladPort = 9010;           // olad's RPC port on this machine
  std::vector<Fixture> fixtures;
  bool operator==(const Patch&) const = default;
};

// Throws vitrine::Error "NAME:LINE: REASON" for the first thing wrong: not JSON, an unknown key, a
// fixture type or signal, an address outside 1..512 or a fixture running past 512, two fixtures
// sharing a channel (naming the other's line), more than kMaxPixels pixels, kMaxFixtures fixtures.
Patch parsePatch(std::string_view text, const std::string& name);
// The same from a file (a regular file of at most 1 MiB).
Patch loadPatch(const std::filesystem::path& path);

}  // namespace vitrine::lights
