#include "app/options.h"

#include "app/flags.h"
#include "app/values.h"
#include "core/error.h"
#include "core/output_path.h"
#include "image/image_io.h"
#include "scenes/catalogue.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <string_view>

namespace vitrine {
namespace {

constexpr uint32_t kMaxWindowSide = 16384;  // the gallery's --size; headless sizes meet the device's limit

// A flag outside its modes is refused, naming the mode, rather than ignored in silence (`--headless
// --fps 10` would render at 60 all the same): "--fps is only for record runs, not --headless."
void checkFlagsApply(const std::vector<const flags::Flag*>& given, Mode mode) {
  const unsigned bit = flags::checkedBit(mode);
  if (bit == 0) return;
  for (const flags::Flag* flag : given)
    if (!(flag->modes & bit))
      throw Error(fmt::format("{} is only for {}, not {}.", flag->name, flags::modeList(flag->modes),
                              flags::modeTitle(bit)));
}

}  // namespace

VkExtent2D parseSize(const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos) throw Error(fmt::format("--size expects WIDTHxHEIGHT such as 1920x1080, not '{}'.", text));
  const auto width = wholeNumber(std::string_view(text).substr(0, x), 1, kMaxWhole);
  const auto height = wholeNumber(std::string_view(text).substr(x + 1), 1, kMaxWhole);
  if (!width || !height)
    throw Error(
        fmt::format("--size expects WIDTHxHEIGHT, each a whole number from 1 to {}, not '{}'.", kMaxWhole, text));
  return {*width, *height};
}

Options parseOptions(int argc, const char* const* argv) {
  Options options;
  if (const char* env = std::getenv("VITRINE_VALIDATION"); env && std::string_view(env) == "1")
    options.validation = true;
  int i = 1;
  if (const flags::ModeInfo* command = argc > 1 ? flags::subcommand(argv[1]) : nullptr) {
    options.mode = command->mode;
    if (options.mode == Mode::Bench) options.frames = 200;
    ++i;
  }
  auto value = [&](std::string_view flag) -> std::string {
    if (i + 1 >= argc) throw Error(fmt::format("{} needs a value; see vitrine --help.", flag));
    if (const std::string_view next = argv[i + 1]; next.size() > 2 && next.starts_with("--"))
      throw Error(fmt::format("{} needs a value, but got the option {}.", flag, next));
    return argv[++i];
  };
  std::vector<const flags::Flag*> given;
  for (; i < argc; ++i) {
    const std::string_view arg = argv[i];
    const flags::Flag* flag = flags::find(arg);
    if (!flag) {
      // The operands: encode's FOLDER, compare's two images.
      if (options.mode == Mode::Encode && !arg.starts_with("-")) {
        if (!options.sequence.empty())
          throw Error(fmt::format("encode takes one FOLDER, not both {} and {}.", options.sequence, arg));
        options.sequence = arg;
      } else if (options.mode == Mode::Compare && !arg.starts_with("--")) {
        options.compare.emplace_back(arg);
      } else {
        throw Error(fmt::format("Unknown option '{}'; see vitrine --help.", arg));
      }
      continue;
    }
    // One given twice is refused unless repeatable, as the second would silently win. A listing picks
    // a mode of its own and may be given again.
    if (!flag->repeatable && !(flag->modes & flags::kListing) && std::ranges::find(given, flag) != given.end())
      throw Error(fmt::format("{} is given twice; only {} may be given more than once.", arg, flags::repeatableList()));
    given.push_back(flag);
    std::string text;
    if (flag->value == flags::Value::OptionalScene) {
      if (i + 1 < argc && argv[i + 1][0] != '-') text = argv[++i];
    } else if (flag->value != flags::Value::None) {
      text = value(arg);
    }
    flag->store(options, flag->name, text);
  }
  checkFlagsApply(given, options.mode);
  if (options.mode == Mode::Compare && options.compare.size() != 2)
    throw Error("compare expects two EXR files: REFERENCE CANDIDATE.");
  auto isGiven = [&](std::string_view name) {
    return std::ranges::any_of(given, [&](const flags::Flag* flag) { return flag->name == name; });
  };
  if (options.mode == Mode::Headless && options.out.empty())
    throw Error("--headless needs --out FILE.exr (or FILE.png).");
  if (options.mode == Mode::Bench && options.out.empty()) throw Error("bench needs --json FILE.");
  if (options.mode == Mode::Headless && options.scene.empty()) throw Error("--headless needs --scene NAME (or --isf FILE).");
  if (options.mode == Mode::Headless && !imageFormatFromName(options.out))
    throw Error(fmt::format("--out writes .exr (linear half float) or .png (8-bit sRGB), not '{}'.", options.out));
  if (options.span && !options.monitor.empty())
    throw Error("--span covers every monitor with one window: drop --monitor.");
  if (options.mode == Mode::Record) {
    if (options.scene.empty()) throw Error("record needs --scene NAME (or --isf FILE).");
    if (options.out.empty()) throw Error("record needs --out FOLDER for the numbered frames.");
    if (!(options.seconds > 0.0)) throw Error("record needs --seconds S, the film's length.");
    if (options.spp > kMaxRecordSpp) throw Error(fmt::format("--spp takes 1 to {} samples a frame.", kMaxRecordSpp));
    if (options.checkpointsOnly && options.checkpointEvery == 0)
      throw Error("--checkpoints-only writes checkpoints: say how often with --checkpoint-every N.");
    if (film::isFilmName(options.out)) {
      if (options.range)
        throw Error(fmt::format("--range is for a sequence of frames in a folder; {} is a film, rendered whole: "
                                "drop --range, or record into a folder and run vitrine encode on it.", options.out));
      if (options.checkpointEvery > 0)
        throw Error(fmt::format("--checkpoint-every keeps state beside a sequence of frames; {} is a film, rendered "
                                "whole in one run: record into a folder and run vitrine encode on it.", options.out));
      if (isGiven("--format"))
        throw Error(fmt::format("--format picks the frames' files in a folder; {} is a film, encoded as --codec says.",
                                options.out));
      // The codec, the container and the size agree, and the film can be written, before anything renders.
      const VkExtent2D size = options.size.value_or(kRecordSize);
      (void)film::resolveFilm(options.out, options.film, size.width, size.height);
      checkWritable(options.out);
    } else {
      if (const std::string other = film::otherMediaExtension(options.out); !other.empty())
        throw Error(fmt::format("record writes a film as .mp4, .mov or .mkv, or frames into a folder; '{}' names a {} "
                                "file, which this build does not write: name the folder without {}.",
                                options.out, other, std::filesystem::path(options.out).extension().string()));
      // The flags record shares only with encode shape a film's encoding.
      for (const flags::Flag* flag : given)
        if (flag->modes == (flags::kRecord | flags::kEncode))
          throw Error(fmt::format("{} is for a film: --out NAME.mp4, .mov or .mkv, not the folder {}.", flag->name,
                                  options.out));
    }
  }
  if (options.mode == Mode::Encode) {
    if (options.sequence.empty())
      throw Error("encode needs the FOLDER of a recorded sequence: vitrine encode FOLDER --out film.mp4.");
    if (options.out.empty()) throw Error("encode needs --out NAME.mp4, .mov or .mkv.");
    if (!film::isFilmName(options.out))
      throw Error(fmt::format("encode writes a film: --out NAME.mp4, .mov or .mkv, not '{}'.", options.out));
    checkWritable(options.out);
  }
  const bool scripted = options.mode == Mode::Headless || options.mode == Mode::Record;
  if (!options.input.empty() && !scripted) throw Error("--input is only for --headless and record runs.");
  if (!options.events.empty() && !scripted) throw Error("--events is only for --headless and record runs.");
  if (!options.events.empty()) checkWritable(options.events);
  if (!options.audioOut.empty()) {
    if (options.mode != Mode::Headless) throw Error("--audio-out is only for --headless runs.");
    if (lowercase(std::filesystem::path(options.audioOut).extension().string()) != ".wav") throw Error(fmt::format("--audio-out writes WAV: name it FILE.wav, not '{}'.", options.audioOut));
    checkWritable(options.audioOut);
  }
  if (!options.audioIn.empty() && !options.audioInDevice.empty())
    throw Error("--audio-in FILE and --audio-in-device both feed the audio sources: give one of them.");
  if (options.mode == Mode::ExportPreset && options.out.empty())
    throw Error("--export-preset needs --out FILE.json, where the preset's file is written.");
  if (!options.playlist.empty() && !options.kiosk) throw Error("--playlist is the kiosk's: give --kiosk too.");
  if (!options.playlist.empty() && isGiven("--dwell"))
    throw Error("--dwell and --playlist both say how long a scene shows: the playlist gives each line's dwell.");
  if (options.kiosk && options.mode != Mode::Gallery) throw Error("--kiosk is for the gallery, not --headless, bench or record.");
  if (options.remote && options.mode != Mode::Gallery && options.mode != Mode::Headless)
    throw Error("--remote is for the gallery and --headless runs.");
  if (!options.transitionParameters.empty() && options.transition.empty())
    throw Error("--set transition.KEY=VALUE needs --transition FILE (the gallery's), whose input it sets.");
  if (options.remoteSaves && !options.remote) throw Error("--remote-saves needs --remote.");
  if (!options.remoteAllow.empty() && !options.remote) throw Error("--remote-allow needs --remote.");
  if (options.mode == Mode::Gallery && options.size &&
      (options.size->width > kMaxWindowSide || options.size->height > kMaxWindowSide))
    throw Error(fmt::format("--size expects each side of the gallery window from 1 to {}, not '{}x{}'.",
                            kMaxWindowSide, options.size->width, options.size->height));
  return options;
}

std::vector<std::pair<std::string, std::string>> parametersFor(const Options& options, std::string_view scene,
                                                               bool unqualifiedToo) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& setting : options.parameters)
    if (setting.scene == scene || (unqualifiedToo && setting.scene.empty())) pairs.emplace_back(setting.key, setting.value);
  return pairs;
}

std::vector<std::string> presetsFor(const Options& options, std::string_view scene, bool unqualifiedToo) {
  std::vector<std::string> names;
  for (const auto& preset : options.presets)
    if (preset.scene == scene || (unqualifiedToo && preset.scene.empty())) names.push_back(preset.key);
  return names;
}

}  // namespace vitrine
