#pragma once
// A mapping binds a live source (audio.bass, midi.cc.1.20, pad.0.axis.1, osc.fader, lfo.sine.8) to a
// scene's parameter or action. It is one line of text everywhere it is written: the command line
// (--map), mapping files, the settings file, the panel and the remote page:
//
//   SOURCE=[SCENE.]TARGET[:LO:HI] [curve=linear|ease-in|ease-out|smooth|log] [attack=S] [release=S]
//                                 [takeover=soft|jump] [args=X,Y,Z]
//
//   audio.bass=kifs.fold:1:1.12 release=0.25     the bass folds the fractal, falling back over 0.25 s
//   midi.cc.1.21=glass.abbe:60:4 curve=log       a knob from low to high dispersion, soft takeover
//   audio.beat=neon.burst                         an action, fired as the source rises through one half
//
// Every source reads 0..1. A value goes: source -> smoothing (attack when rising, release when falling:
// one-pole time constants in seconds) -> curve -> LO..HI (LO may exceed HI: the mapping runs backwards;
// both default to the parameter's range) -> the parameter's own parse, exactly as --set. An unqualified
// TARGET belongs to the scene the mapping is given for (the scene running, for --map).
#include "params/schema.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {
struct SceneInfo;
}

namespace vitrine::live {

enum class Curve { Linear, EaseIn, EaseOut, Smooth, Log };
enum class Takeover { Jump, Soft };

struct Mapping {
  std::string source;                  // "audio.bass"
  std::string scene;                   // "kifs"; empty: the scene it is given for
  std::string target;                  // a parameter's key or an action's name
  std::optional<std::string> lo, hi;   // the range as the parameter's text ("0.9", "pill"); none: its whole range
  Curve curve = Curve::Linear;
  float attack = 0.0f, release = 0.0f;  // seconds
  std::optional<Takeover> takeover;     // none: soft for MIDI controls, jump for everything else
  std::vector<float> args;              // an action's arguments
  bool operator==(const Mapping&) const = default;

  Takeover takeoverMode() const;
};

// Parses one mapping line; nullopt with the reason in *error. Judges form and the source's name only:
// whether the target exists is checkMapping's.
std::optional<Mapping> parseMapping(std::string_view text, std::string* error);
// The canonical line: parseMapping(formatMapping(m)) == m. Options at their defaults are left out.
std::string formatMapping(const Mapping& mapping);

// "" when `name` is a source Vitrine can give, else why not (names every family).
std::string checkSourceName(std::string_view name);

// A mapping checked against the scene it targets (`scene`: the scene named, or the one it is given for).
// Refused, with a reason: an unknown parameter or action, a parameter that rebuilds GPU resources (it
// would rebuild them every frame), a colour or custom parameter, a range outside the parameter's, a
// range on a bool or an action, arguments that do not fit the action.
std::string checkMapping(const Mapping& mapping, const SceneInfo& scene);

// A mapping file: one mapping per line, '#' starts a comment, blank lines ignored. Throws vitrine::Error
// "FILE:LINE: REASON" for the first bad line (every target checked against its scene: a mapping file
// qualifies each target with its scene). At most 4096 lines of 1024 characters.
std::vector<Mapping> loadMappingFile(const std::filesystem::path& path);
std::vector<Mapping> parseMappingText(std::string_view text, const std::string& name);  // the same, from memory
// Writes atomically, one formatted line per mapping, under a comment naming the format.
void saveMappingFile(const std::filesystem::path& path, const std::vector<Mapping>& mappings);

}  // namespace vitrine::live
