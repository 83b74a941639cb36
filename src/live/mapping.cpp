#include "live/mapping.h"

#include "core/bounded_file.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "scenes/catalogue.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

namespace vitrine::live {
namespace {

constexpr size_t kMaxLines = 4096, kMaxLineLength = 1024, kMaxArgs = 8;
constexpr std::array kCurves{"linear", "ease-in", "ease-out", "smooth", "log"};
constexpr std::array kAudioSources{"bass", "mid", "high", "level", "onset", "beat", "tempo"};
constexpr std::array kLfoShapes{"sine", "triangle", "saw", "square"};
constexpr std::array kLinkSources{"tempo", "beat", "phase", "bar", "playing", "pulse"};
constexpr std::array kClockSources{"tempo", "beat", "phase", "bar", "running"};
constexpr std::array kTimecodeSources{"seconds", "minutes", "locked"};

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  for (size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == separator) parts.push_back(text.substr(start, i - start)), start = i + 1;
  return parts;
}

bool plainWord(std::string_view word) {
  return !word.empty() && word.size() <= 64 && std::all_of(word.begin(), word.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  });
}

// Canonical digits only ("7", not "07"): a source's name is matched as text.
bool wholeNumber(std::string_view text, int min, int max) {
  if (text.size() > 1 && text[0] == '0') return false;
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && value >= min && value <= max;
}

bool number(std::string_view text, float min, float max, float& out) {
  return params::parseFloatText(text, min, max, out, nullptr);
}

template <size_t N> bool oneOf(std::string_view word, const std::array<const char*, N>& names) {
  return std::find(names.begin(), names.end(), word) != names.end();
}

std::string sourceFamilies() {
  return "sources are audio.bass|mid|high|level|onset|beat|tempo, midi.cc.CHANNEL.NUMBER, "
         "midi.note.CHANNEL.NUMBER, midi.gate.CHANNEL.NUMBER, midi.clock.tempo|beat|phase|bar|running, "
         "mtc.seconds|minutes|locked, ltc.seconds|minutes|locked, pad.N.axis.K, pad.N.button.K, osc.NAME, "
         "lfo.sine|triangle|saw|square.PERIOD, link.tempo|beat|phase|bar|playing|pulse, dmx.UNIVERSE.CHANNEL and "
         "dmx16.UNIVERSE.CHANNEL";
}

}  // namespace

Takeover Mapping::takeoverMode() const {
  // A fader or knob on a desk: it may stand elsewhere than the parameter when the mapping begins.
  const bool control = source.starts_with("midi.cc.") || source.starts_with("dmx.") || source.starts_with("dmx16.");
  return takeover.value_or(control ? Takeover::Soft : Takeover::Jump);
}

std::string checkSourceName(std::string_view name) {
  const auto parts = split(name, '.');
  const auto bad = [&](std::string_view why) { return fmt::format("'{}' is not a source: {}", name, why); };
  const std::string_view family = parts[0];
  if (family == "audio") {
    if (parts.size() == 2 && oneOf(parts[1], kAudioSources)) return {};
    return bad("audio sources are audio.bass, .mid, .high, .level, .onset, .beat and .tempo");
  }
  if (family == "midi") {
    if (parts.size() >= 2 && parts[1] == "clock") {
      if (parts.size() == 3 && oneOf(parts[2], kClockSources)) return {};
      return bad("MIDI clock sources are midi.clock.tempo, .beat, .phase, .bar and .running");
    }
    if (parts.size() == 4 && (parts[1] == "cc" || parts[1] == "note" || parts[1] == "gate") &&
        wholeNumber(parts[2], 1, 16) && wholeNumber(parts[3], 0, 127))
      return {};
    return bad("MIDI sources are midi.cc|note|gate.CHANNEL.NUMBER, channel 1..16, number 0..127");
  }
  if (family == "mtc" || family == "ltc") {
    if (parts.size() == 2 && oneOf(parts[1], kTimecodeSources)) return {};
    return bad(fmt::format("timecode sources are {0}.seconds, {0}.minutes and {0}.locked", family));
  }
  if (family == "pad") {
    if (parts.size() == 4 && wholeNumber(parts[1], 0, 15) &&
        ((parts[2] == "axis" && wholeNumber(parts[3], 0, 5)) || (parts[2] == "button" && wholeNumber(parts[3], 0, 14))))
      return {};
    return bad("gamepad sources are pad.N.axis.K (N 0..15, K 0..5) and pad.N.button.K (K 0..14)");
  }
  if (family == "osc") {
    if (parts.size() == 2 && plainWord(parts[1])) return {};
    return bad("OSC sources are osc.NAME, set by /vitrine/mod/NAME (letters, digits, _ and -)");
  }
  if (family == "lfo") {
    float period = 0.0f;
    const size_t shapeEnd = name.find('.', 4);
    if (parts.size() >= 3 && oneOf(parts[1], kLfoShapes) && shapeEnd != std::string_view::npos &&
        number(name.substr(shapeEnd + 1), 0.01f, 3600.0f, period))
      return {};
    return bad("LFOs are lfo.sine|triangle|saw|square.PERIOD, PERIOD in seconds from 0.01 to 3600");
  }
  if (family == "link") {
    if (parts.size() == 2 && oneOf(parts[1], kLinkSources)) return {};
    return bad("Ableton Link sources are link.tempo, .beat, .phase, .bar, .playing and .pulse");
  }
  if (family == "dmx" || family == "dmx16") {
    // Universes as olad numbers them; channels from 1, a 16-bit pair's coarse one below 512.
    if (parts.size() == 3 && wholeNumber(parts[1], 0, 65535) && wholeNumber(parts[2], 1, family == "dmx" ? 512 : 511)) return {};
    return bad("DMX sources are dmx.UNIVERSE.CHANNEL (channel 1..512) and dmx16.UNIVERSE.CHANNEL (the 16-bit pair of "
               "CHANNEL and the next, 1..511), universe 0..65535");
  }
  return bad(sourceFamilies());
}

std::optional<Mapping> parseMapping(std::string_view text, std::string* error) {
  const auto fail = [&](std::string why) -> std::optional<Mapping> {
    if (error) *error = std::move(why);
    return std::nullopt;
  };
  std::vector<std::string_view> words;
  for (std::string_view word : split(text, ' '))
    if (!word.empty()) words.push_back(word);
  if (words.empty()) return fail("an empty mapping; expected SOURCE=[SCENE.]TARGET[:LO:HI] [options]");
  const std::string_view binding = words[0];
  const size_t equals = binding.find('=');
  if (equals == std::string_view::npos)
    return fail(fmt::format("'{}' has no '='; expected SOURCE=[SCENE.]TARGET[:LO:HI]", binding));
  Mapping mapping;
  mapping.source = binding.substr(0, equals);
  if (auto why = checkSourceName(mapping.source); !why.empty()) return fail(why);

  const auto range = split(binding.substr(equals + 1), ':');
  if (range.size() != 1 && range.size() != 3)
    return fail(fmt::format("'{}': a range is two values, TARGET:LO:HI", binding.substr(equals + 1)));
  const auto target = split(range[0], '.');
  if (target.size() > 2 || !std::all_of(target.begin(), target.end(), plainWord))
    return fail(fmt::format("'{}' is not a target; expected KEY or SCENE.KEY", range[0]));
  mapping.target = target.back();
  if (target.size() == 2) mapping.scene = target[0];
  if (range.size() == 3) {
    if (range[1].empty() || range[2].empty()) return fail("a range needs both ends, TARGET:LO:HI");
    mapping.lo = std::string(range[1]), mapping.hi = std::string(range[2]);
  }

  for (size_t i = 1; i < words.size(); ++i) {
    const size_t eq = words[i].find('=');
    const std::string_view key = words[i].substr(0, eq), value = eq == std::string_view::npos ? "" : words[i].substr(eq + 1);
    if (eq == std::string_view::npos || value.empty())
      return fail(fmt::format("'{}': options are curve=, attack=, release=, takeover= and args=", words[i]));
    if (key == "curve") {
      const auto found = std::find(kCurves.begin(), kCurves.end(), value);
      if (found == kCurves.end()) return fail(fmt::format("curve={}: expected linear, ease-in, ease-out, smooth or log", value));
      mapping.curve = Curve(found - kCurves.begin());
    } else if (key == "attack" || key == "release") {
      float seconds = 0.0f;
      if (!number(value, 0.0f, 60.0f, seconds)) return fail(fmt::format("{}={}: expected seconds from 0 to 60", key, value));
      (key == "attack" ? mapping.attack : mapping.release) = seconds;
    } else if (key == "takeover") {
      if (value != "soft" && value != "jump") return fail(fmt::format("takeover={}: expected soft or jump", value));
      mapping.takeover = value == "soft" ? Takeover::Soft : Takeover::Jump;
    } else if (key == "args") {
      for (std::string_view arg : split(value, ',')) {
        float x = 0.0f;
        if (!number(arg, -1e6f, 1e6f, x) || mapping.args.size() == kMaxArgs)
          return fail(fmt::format("args={}: expected up to {} numbers separated by commas", value, kMaxArgs));
        mapping.args.push_back(x);
      }
    } else {
      return fail(fmt::format("unknown option '{}'; options are curve=, attack=, release=, takeover= and args=", key));
    }
  }
  return mapping;
}

std::string formatMapping(const Mapping& m) {
  std::string text = fmt::format("{}={}{}", m.source, m.scene.empty() ? "" : m.scene + ".", m.target);
  if (m.lo && m.hi) text += fmt::format(":{}:{}", *m.lo, *m.hi);
  if (m.curve != Curve::Linear) text += fmt::format(" curve={}", kCurves[size_t(m.curve)]);
  if (m.attack > 0.0f) text += " attack=" + params::formatFloat(m.attack);
  if (m.release > 0.0f) text += " release=" + params::formatFloat(m.release);
  if (m.takeover) text += *m.takeover == Takeover::Soft ? " takeover=soft" : " takeover=jump";
  if (!m.args.empty()) {
    std::vector<std::string> args;
    for (const float arg : m.args) args.push_back(params::formatFloat(arg));
    text += fmt::format(" args={}", fmt::join(args, ","));
  }
  return text;
}

std::string checkMapping(const Mapping& mapping, const SceneInfo& scene) {
  if (!mapping.scene.empty() && mapping.scene != scene.name)
    return fmt::format("the mapping is for {}, not {}", mapping.scene, scene.name);
  const std::string where = fmt::format("{}.{}", scene.name, mapping.target);
  if (scene.findAction(mapping.target)) {
    if (mapping.lo) return fmt::format("{} is an action: it fires as the source rises through one half, with no range", where);
    if (auto why = checkAction(scene, {mapping.target, mapping.args}); !why.empty())
      return fmt::format("{}: {} (give them with args=)", where, why);
    return {};
  }
  const params::Param* param = scene.schema().find(mapping.target);
  if (!param) return fmt::format("{} names no parameter or action of {} (vitrine --list-params {})", where, scene.name, scene.name);
  if (param->has(params::kRebuilds))
    return fmt::format("{} rebuilds the scene's GPU resources when it changes; a mapping would rebuild them every frame", where);
  if (param->kind == params::Kind::Colour || param->kind == params::Kind::Custom)
    return fmt::format("{} is a {} parameter; mappings drive numbers, switches and choices", where,
                       param->kind == params::Kind::Colour ? "colour" : "structured");
  if (!mapping.args.empty()) return fmt::format("{} is a parameter: args= is for actions", where);
  if (mapping.curve == Curve::Log && param->kind != params::Kind::Float && param->kind != params::Kind::Int)
    return fmt::format("{}: curve=log is for numbers", where);
  if (!mapping.lo) return {};
  if (param->kind == params::Kind::Bool) return fmt::format("{} is a switch: it is on above one half, with no range", where);
  const auto scratch = scene.schema().makeDefaults();
  for (const std::string* end : {&*mapping.lo, &*mapping.hi}) {
    std::string why;
    if (!param->parse(scratch.get(), *end, &why)) return fmt::format("{}: the range's end {}: {}", where, *end, why);
  }
  if (mapping.curve == Curve::Log) {
    param->parse(scratch.get(), *mapping.lo, nullptr);
    const double lo = param->number(scratch.get());
    param->parse(scratch.get(), *mapping.hi, nullptr);
    if (!(lo > 0.0 && param->number(scratch.get()) > 0.0)) return fmt::format("{}: curve=log needs a range above 0", where);
  }
  return {};
}

std::vector<Mapping> parseMappingText(std::string_view text, const std::string& name) {
  std::vector<Mapping> mappings;
  if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);  // a UTF-8 byte-order mark, as editors write
  if (text.ends_with('\n')) text.remove_suffix(1);                 // a final newline ends the last line
  size_t lineNumber = 0;
  for (std::string_view line : split(text, '\n')) {
    ++lineNumber;
    const auto fail = [&](const std::string& why) { return Error(fmt::format("{}:{}: {}", name, lineNumber, why)); };
    if (lineNumber > kMaxLines) throw fail(fmt::format("a mapping file has at most {} lines", kMaxLines));
    if (line.size() > kMaxLineLength) throw fail(fmt::format("a line has at most {} characters", kMaxLineLength));
    if (const size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::string cleaned(line);
    std::replace(cleaned.begin(), cleaned.end(), '\t', ' ');
    if (cleaned.find_first_not_of(' ') == std::string::npos) continue;
    for (const char c : cleaned)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f)
        throw fail("a mapping is plain ASCII text");
    std::string why;
    auto mapping = parseMapping(cleaned, &why);
    if (!mapping) throw fail(why);
    if (mapping->scene.empty())
      throw fail(fmt::format("'{}': a mapping file names the scene of each target, SCENE.{}", mapping->target, mapping->target));
    const SceneInfo* scene = findScene(mapping->scene);
    if (!scene) throw fail(unknownScene(mapping->scene));
    if (auto reason = checkMapping(*mapping, *scene); !reason.empty()) throw fail(reason);
    mappings.push_back(std::move(*mapping));
  }
  return mappings;
}

std::vector<Mapping> loadMappingFile(const std::filesystem::path& path) {
  try {  // each line may end in CR LF
    return parseMappingText(readBoundedFile(path, kMaxLines * (kMaxLineLength + 2)), path.string());
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read the mapping file {}: {}", path.string(), refused.why));
  }
}

void saveMappingFile(const std::filesystem::path& path, const std::vector<Mapping>& mappings) {
  std::string text = "# Vitrine mappings: SOURCE=SCENE.TARGET[:LO:HI] [curve= attack= release= takeover= args=]\n";
  for (const Mapping& mapping : mappings) text += formatMapping(mapping) + "\n";
  writeFileAtomically(path, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
}

}  // namespace vitrine::live
