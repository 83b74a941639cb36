#include "app/options.h"

#include "core/error.h"
#include "core/output_path.h"
#include "image/image_io.h"
#include "scenes/catalogue.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <limits>
#include <optional>
#include <string_view>

namespace vitrine {
namespace {

constexpr uint32_t kMaxWindowSide = 16384;  // the gallery's --size; headless sizes meet the device's limit
constexpr uint32_t kMaxWhole = std::numeric_limits<uint32_t>::max();

// A whole number in [min, max]; nothing for anything else (a sign, a fraction, too many digits).
std::optional<uint32_t> wholeNumber(std::string_view text, uint32_t min, uint32_t max) {
  uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max) return std::nullopt;
  return uint32_t(value);
}

uint32_t parseWhole(std::string_view flag, std::string_view text, uint32_t min, uint32_t max = kMaxWhole) {
  if (const auto value = wholeNumber(text, min, max)) return *value;
  throw Error(fmt::format("{} expects a whole number from {} to {}, not '{}'.", flag, min, max, text));
}

double parseSeconds(std::string_view flag, std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw Error(fmt::format("{} expects a finite number of seconds, not '{}'.", flag, text));
  return value;
}

// A finite number above 0 and at most max (frames a second, a film's seconds).
double parsePositive(std::string_view flag, std::string_view text, double max) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !(value > 0.0) || !(value <= max))
    throw Error(fmt::format("{} expects a number above 0 and at most {}, not '{}'.", flag, max, text));
  return value;
}

// "A:B": frames A up to, not including, B.
std::pair<uint32_t, uint32_t> parseRange(std::string_view text) {
  const auto colon = text.find(':');
  const auto a = colon == std::string_view::npos ? std::nullopt : wholeNumber(text.substr(0, colon), 0, kMaxWhole);
  const auto b = colon == std::string_view::npos ? std::nullopt : wholeNumber(text.substr(colon + 1), 0, kMaxWhole);
  if (!a || !b || *a >= *b)
    throw Error(fmt::format("--range expects FIRST:END, frames FIRST up to but not including END, not '{}'.", text));
  return {*a, *b};
}

// "SCENE.NAME" or "NAME": split at the '.', which neither scene names nor keys contain. Nothing when
// either side is empty or there is a second '.'. An unknown scene is an error naming `flag` and `text`.
std::optional<SceneSetting> qualifiedName(std::string_view flag, std::string_view name, std::string_view text) {
  SceneSetting setting;
  if (const auto dot = name.find('.'); dot != std::string_view::npos) {
    setting.scene = name.substr(0, dot);
    name.remove_prefix(dot + 1);
    if (setting.scene.empty()) return std::nullopt;
    if (!findScene(setting.scene)) throw Error(unknownScene(setting.scene, fmt::format(" in {} {}", flag, text)));
  }
  if (name.empty() || name.find('.') != std::string_view::npos) return std::nullopt;
  setting.key = name;
  return setting;
}

SceneSetting parseSet(std::string_view text) {
  const auto eq = text.find('=');
  std::optional<SceneSetting> setting;
  if (eq != std::string_view::npos) setting = qualifiedName("--set", text.substr(0, eq), text);
  if (!setting) throw Error(fmt::format("--set expects KEY=VALUE or SCENE.KEY=VALUE, not '{}'.", text));
  setting->value = text.substr(eq + 1);
  return *setting;
}

SceneSetting parsePreset(std::string_view text) {
  std::optional<SceneSetting> preset;
  if (text.find('=') == std::string_view::npos) preset = qualifiedName("--preset", text, text);
  if (!preset) throw Error(fmt::format("--preset expects NAME or SCENE.NAME, not '{}'.", text));
  return *preset;
}

std::string lowercase(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// Which of the run modes each flag applies to, and whether it may be given more than once. A flag
// outside its modes is refused, naming the mode, rather than ignored in silence (`--headless --fps 10`
// would render at 60 all the same); one given twice is refused unless repeatable, as the second would
// silently win. Flags not listed here (the --list-* modes, --help, --version) are checked by their own rules.
enum ModeBits : unsigned { kGallery = 1, kHeadless = 2, kBench = 4, kRecord = 8, kEncode = 16, kRuns = 15 };

struct FlagRule {
  std::string_view name;
  unsigned modes;
  bool repeatable = false;
};

constexpr FlagRule kFlagRules[] = {
    {"--headless", kHeadless},
    {"--scene", kRuns},
    {"--device", kRuns},
    {"--validate", kRuns},
    {"--reduced-motion", kRuns},
    {"--monitor", kGallery},
    {"--output-warp", kGallery | kHeadless},
    {"--outputs", kGallery},
    {"--span", kGallery},
    {"--flash-guard", kRuns},
    {"--seed", kRuns},
    {"--size", kRuns},
    {"--set", kRuns, true},
    {"--preset", kRuns, true},
    {"--preset-file", kRuns, true},
    {"--save-preset", kHeadless},
    {"--frames", kHeadless | kBench},
    {"--time", kHeadless | kBench | kRecord},
    {"--out", kHeadless | kRecord | kEncode},
    {"--json", kBench},
    {"--pipeline-stats", kBench},
    {"--warmup", kBench},
    {"--fullscreen", kGallery},
    {"--no-vsync", kGallery},
    {"--reset-settings", kGallery},
    {"--kiosk", kGallery},
    {"--dwell", kGallery},
    {"--playlist", kGallery},
    {"--remote", kGallery | kHeadless},
    {"--remote-bind", kGallery | kHeadless},
    {"--remote-saves", kGallery},
    {"--remote-allow", kGallery | kHeadless, true},
    {"--input", kHeadless | kRecord},
    {"--events", kHeadless | kRecord},
    {"--audio-out", kHeadless},
    {"--map", kGallery | kHeadless | kRecord, true},
    {"--audio-in", kGallery | kHeadless | kRecord},
    {"--audio-in-device", kGallery},
    {"--midi-in", kHeadless | kRecord},
    {"--fps", kRecord},
    {"--seconds", kRecord},
    {"--spp", kRecord},
    {"--range", kRecord},
    {"--checkpoint-every", kRecord},
    {"--checkpoints-only", kRecord},
    {"--format", kRecord},
    {"--codec", kRecord | kEncode},
    {"--crf", kRecord | kEncode},
    {"--bitrate", kRecord | kEncode},
    {"--pix-fmt", kRecord | kEncode},
    {"--full-range", kRecord | kEncode},
};

// The flags that shape a film's encoding: refused for a record run into a folder of frames.
constexpr std::string_view kFilmFlags[] = {"--codec", "--crf", "--bitrate", "--pix-fmt", "--full-range"};

const FlagRule* findFlagRule(std::string_view flag) {
  for (const FlagRule& rule : kFlagRules)
    if (rule.name == flag) return &rule;
  return nullptr;
}

unsigned modeBit(Mode mode) {
  switch (mode) {
    case Mode::Gallery: return kGallery;
    case Mode::Headless: return kHeadless;
    case Mode::Bench: return kBench;
    case Mode::Record: return kRecord;
    case Mode::Encode: return kEncode;
    default: return 0;  // the listing and help modes take what they need and ignore the rest
  }
}

std::string_view modeName(unsigned bit) {
  switch (bit) {
    case kGallery: return "the gallery";
    case kHeadless: return "--headless";
    case kBench: return "bench";
    case kEncode: return "encode";
    default: return "record";
  }
}

// "--headless and record runs", "the gallery", "bench runs".
std::string modeList(unsigned modes) {
  std::vector<std::string_view> names;
  for (const unsigned bit : {kGallery, kHeadless, kBench, kRecord, kEncode})
    if (modes & bit) names.push_back(modeName(bit));
  std::string text;
  for (size_t n = 0; n < names.size(); ++n)
    text += fmt::format("{}{}", n == 0 ? "" : n + 1 == names.size() ? " and " : ", ", names[n]);
  return modes == kGallery ? text : text + " runs";
}

// Throws for a flag given to a run mode it does not apply to: "--fps is only for record runs, not --headless."
void checkFlagsApply(const std::vector<const FlagRule*>& given, Mode mode) {
  const unsigned bit = modeBit(mode);
  if (bit == 0) return;
  for (const FlagRule* rule : given)
    if (!(rule->modes & bit))
      throw Error(fmt::format("{} is only for {}, not {}.", rule->name, modeList(rule->modes), modeName(bit)));
}

}  // namespace

const char* usage() {
  return R"(Vitrine: a gallery of real-time GPU pieces.

  vitrine [--scene NAME] [--size WxH] [--fullscreen] [--no-vsync] [--device INDEX|NAME]
          [--reduced-motion] [--flash-guard on|off] [--seed S] [--set [SCENE.]KEY=VALUE]...
          [--preset [SCENE.]NAME]... [--preset-file FILE]... [--reset-settings] [--validate]
          [--kiosk [--dwell SECONDS | --playlist FILE]]
          [--remote [--remote-bind ADDR:PORT] [--remote-allow CIDR]... [--remote-saves]]
          [--map FILE|SOURCE=[SCENE.]KEY[:LO:HI]]... [--audio-in FILE | --audio-in-device NAME|INDEX|default]
          [--monitor INDEX|NAME | --span] [--output-warp FILE.json] [--outputs FILE.json]
  vitrine --headless --scene NAME [--size WxH] [--frames N] [--time SECONDS] [--seed S]
          [--set [SCENE.]KEY=VALUE]... [--preset [SCENE.]NAME]... [--preset-file FILE]... [--save-preset NAME]
          [--input FILE] [--events FILE] [--audio-out FILE.wav] [--remote [--remote-bind ADDR:PORT] [--remote-allow CIDR]...]
          [--map ...]... [--audio-in FILE] [--midi-in FILE.mid] [--output-warp FILE.json] --out FILE.exr|FILE.png
  vitrine record --scene NAME --seconds S --out FOLDER [--size WxH] [--fps F] [--spp K] [--range A:B]
          [--checkpoint-every N [--checkpoints-only]] [--format exr|png] [--time SECONDS] [--seed S]
          [--set ...] [--preset ...] [--input FILE] [--events FILE] [--map ...]... [--audio-in FILE]
          [--midi-in FILE.mid]
  vitrine record ... --out FILM.mp4|FILM.mov|FILM.mkv [--codec h264|hevc|prores|prores4444|ffv1]
          [--crf N | --bitrate N[k|M]] [--pix-fmt yuv420p|yuv444p|yuv420p10le|yuv444p10le] [--full-range]
  vitrine encode FOLDER --out FILM.mp4|FILM.mov|FILM.mkv [--codec ...] [--crf N | --bitrate N[k|M]] [--pix-fmt ...]
          [--full-range]
  vitrine bench --scene NAME|all [--size WxH] [--frames N] [--warmup N] [--set [SCENE.]KEY=VALUE]...
          [--preset [SCENE.]NAME]... [--pipeline-stats] --json FILE
  vitrine compare [--fail-fraction F] [--hard-limit H] [--lowpass N] REFERENCE.exr CANDIDATE.exr
  vitrine --list-params [SCENE]
  vitrine --export-preset [SCENE.]NAME --out FILE.json
  vitrine --list-devices | --list-monitors | --list-scenes | --help | --version

Gallery keys: 1-9 switch scene, Tab hides the UI, F1 or ? shows help, V toggles vsync, P pauses, . steps while paused, F5
restarts the scene, M mutes, F7 projector setup, F9 live capture, F11 fullscreen, F12 screenshot, Esc quits.
Headless frame k shows time SECONDS + k/60; the last frame is written.
record renders frame_000000.exr ... at a fixed 1/F s a frame, each the average of K samples spread over
its interval (motion blur, anti-aliasing), skipping frames already in FOLDER; --range A:B renders frames
A..B-1 only, the same pixels whichever machine renders them. Scenes with sound also write audio.wav.
--checkpoint-every N saves the simulation every N frames (FOLDER/checkpoint_NNNNNN.state); a run starts
from the latest checkpoint at or before its first missing frame instead of simulating from frame 0.
--checkpoints-only writes them without drawing a frame (a cheap first job before ranges on many machines).
record --out FILM.mp4 (.mov, .mkv) encodes the frames as they render, with the scene's sound, into one film:
h264 in .mp4, ProRes 422 HQ in .mov, lossless FFV1 in .mkv unless --codec says otherwise; --crf (18 for
h264, 20 for hevc) or --bitrate sets the quality; BT.709, limited range unless --full-range. encode FOLDER
turns a recorded sequence and its audio.wav into a film the same way.
--kiosk shows each scene for --dwell seconds (45) with a cross-fade; a touch holds the scene, cycling resumes
after 30 s alone (the dwell when shorter, 10 s at least). --remote serves a control page for phones and listens for OSC on 127.0.0.1:8730 (--remote-bind
changes it); it prints the page's address with its access token. Bound beyond loopback, OSC is taken only from
--remote-allow networks (192.168.1.0/24) or senders that sent the token. Remote changes are not saved unless --remote-saves.
--monitor puts the window, and F11's fullscreen, on a monitor from --list-monitors (its index or part of its
name). --output-warp FILE.json turns, mirrors, crops, corner-pins and edge-blends the output for a projector
(docs/INSTALLATIONS.md); --outputs FILE.json opens more windows (projectors), each fullscreen on a monitor or
at a place, showing the same frame through its own warp; --span stretches the window over every monitor.
The scene still renders once.
Live input (docs/LIVE.md): --map plays a parameter or action from a source (audio.bass, midi.cc.1.21,
pad.0.axis.1, osc.NAME, lfo.sine.8); --audio-in FILE feeds a sound file (looped in the gallery, frame-exact
in headless and record runs, whose audio.wav then carries it) and turns on the scenes' audio mappings, as
--audio-in-device does with a capture device; --midi-in plays a MIDI file's events against simulation time.
--flash-guard on holds back what would flash more than three times a second over a large area (WCAG 2.3.1, in
every mode; docs/INSTALLATIONS.md); it is on by default with --kiosk and --reduced-motion, off otherwise.
--set and --preset apply to whichever scene runs; SCENE.KEY=VALUE and SCENE.NAME (noodles.grid=32) only to
that scene. --list-params shows each scene's parameters. --preset finds the scene's own presets, then yours (saved
from the panel, a remote or --save-preset NAME, in the presets folder beside the settings file); --preset-file
applies a preset's file (as --export-preset writes it) to its scene, in every mode. --playlist FILE gives the kiosk
its lines of SCENE [PRESET] SECONDS.
A flag outside its mode (--fps in --headless, --json for --out) is refused, as is one given twice, except
--set, --preset and --map. record keeps the film's parameters in FOLDER/record.json and resumes only the same film.
)";
}

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
  if (argc > 1 && std::string_view(argv[1]) == "bench") {
    options.mode = Mode::Bench;
    options.frames = 200;
    ++i;
  } else if (argc > 1 && std::string_view(argv[1]) == "record") {
    options.mode = Mode::Record;
    ++i;
  } else if (argc > 1 && std::string_view(argv[1]) == "encode") {
    options.mode = Mode::Encode;
    ++i;
  } else if (argc > 1 && std::string_view(argv[1]) == "compare") {
    options.mode = Mode::Compare;
    // The golden metric's per-case loosening (tests/golden/cases.txt), so any binary checks a case as
    // the suite does (scripts/golden-cases).
    auto metric = [&](std::string_view flag, double lo, double hi) {
      if (i + 1 >= argc) throw Error(fmt::format("compare {} needs a number.", flag));
      const std::string text = argv[++i];
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end || !(v >= lo && v <= hi))
        throw Error(fmt::format("compare {} takes a number from {:g} to {:g}, not '{}'.", flag, lo, hi, text));
      return v;
    };
    auto& t = options.compareThresholds;
    for (i = 2; i < argc; ++i) {
      const std::string_view arg = argv[i];
      if (arg == "--fail-fraction") t.failFraction = metric(arg, 0.0, 1.0);
      else if (arg == "--hard-limit") t.hardLimit = float(metric(arg, 0.0, 1e9));
      else if (arg == "--lowpass") t.block = int(metric(arg, 0.0, 4096.0));
      else if (arg.starts_with("--")) throw Error(fmt::format("compare does not take {}; see vitrine --help.", arg));
      else options.compare.emplace_back(arg);
    }
    if (options.compare.size() != 2) throw Error("compare expects two EXR files: REFERENCE CANDIDATE.");
    return options;
  }
  auto value = [&](std::string_view flag) -> std::string {
    if (i + 1 >= argc) throw Error(fmt::format("{} needs a value; see vitrine --help.", flag));
    if (const std::string_view next = argv[i + 1]; next.size() > 2 && next.starts_with("--"))
      throw Error(fmt::format("{} needs a value, but got the option {}.", flag, next));
    return argv[++i];
  };
  std::vector<const FlagRule*> given;
  for (; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (const FlagRule* rule = findFlagRule(arg)) {
      if (!rule->repeatable && std::find(given.begin(), given.end(), rule) != given.end())
        throw Error(fmt::format("{} is given twice; only --set, --preset, --preset-file, --map and --remote-allow may be given more than once.", arg));
      given.push_back(rule);
    }
    if (arg == "--headless") options.mode = Mode::Headless;
    else if (arg == "--scene") options.scene = value(arg);
    else if (arg == "--device") options.device = value(arg);
    else if (arg == "--validate") options.validation = true;
    else if (arg == "--pipeline-stats") options.pipelineStats = true;
    else if (arg == "--reduced-motion") options.reducedMotion = true;
    else if (arg == "--monitor") options.monitor = value(arg);
    else if (arg == "--output-warp") options.outputWarp = value(arg);
    else if (arg == "--outputs") options.outputs = value(arg);
    else if (arg == "--span") options.span = true;
    else if (arg == "--flash-guard") {
      const std::string state = lowercase(value(arg));
      if (state != "on" && state != "off")
        throw Error(fmt::format("--flash-guard is on or off, not '{}'.", state));
      options.flashGuard = state == "on";
    }
    else if (arg == "--seed") options.seed = parseWhole(arg, value(arg), 0);
    else if (arg == "--size") options.size = parseSize(value(arg));
    else if (arg == "--frames") options.frames = parseWhole(arg, value(arg), 1);
    else if (arg == "--time") options.time = parseSeconds(arg, value(arg));
    else if (arg == "--out" || arg == "--json") options.out = value(arg);
    else if (arg == "--warmup") options.warmup = parseWhole(arg, value(arg), 0);
    else if (arg == "--fullscreen") options.fullscreen = true;
    else if (arg == "--no-vsync") options.vsync = false;
    else if (arg == "--set") options.parameters.push_back(parseSet(value(arg)));
    else if (arg == "--preset") options.presets.push_back(parsePreset(value(arg)));
    else if (arg == "--preset-file") options.presetFiles.push_back(value(arg));
    else if (arg == "--save-preset") {
      options.savePreset = value(arg);
      if (options.savePreset.empty()) throw Error("--save-preset expects a name for the preset, not ''.");
    }
    else if (arg == "--playlist") options.playlist = value(arg);
    else if (arg == "--export-preset") {
      options.mode = Mode::ExportPreset;
      options.exportPreset = parsePreset(value(arg));
    }
    else if (arg == "--input") options.input = value(arg);
    else if (arg == "--events") options.events = value(arg);
    else if (arg == "--audio-out") options.audioOut = value(arg);
    else if (arg == "--map") options.maps.push_back(value(arg));
    else if (arg == "--audio-in") options.audioIn = value(arg);
    else if (arg == "--audio-in-device") options.audioInDevice = value(arg);
    else if (arg == "--midi-in") options.midiIn = value(arg);
    else if (arg == "--reset-settings") options.resetSettings = true;
    else if (arg == "--kiosk") options.kiosk = options.fullscreen = true;
    else if (arg == "--dwell") options.dwell = parsePositive(arg, value(arg), 86400.0);
    else if (arg == "--remote") options.remote = true;
    else if (arg == "--remote-bind") options.remoteBind = value(arg), options.remote = true;
    else if (arg == "--remote-saves") options.remoteSaves = true;
    else if (arg == "--remote-allow") options.remoteAllow.push_back(value(arg));
    else if (arg == "--fps") options.fps = parsePositive(arg, value(arg), kMaxRecordFps);
    else if (arg == "--seconds") options.seconds = parsePositive(arg, value(arg), 86400.0);
    else if (arg == "--spp") options.spp = parseWhole(arg, value(arg), 1);
    else if (arg == "--range") options.range = parseRange(value(arg));
    else if (arg == "--checkpoint-every") options.checkpointEvery = parseWhole(arg, value(arg), 1);
    else if (arg == "--checkpoints-only") options.checkpointsOnly = true;
    else if (arg == "--format") {
      options.format = lowercase(value(arg));
      if (options.format != "exr" && options.format != "png")
        throw Error(fmt::format("--format writes exr or png, not '{}'.", options.format));
    }
    else if (arg == "--codec") options.film.codec = film::parseCodec(value(arg));
    else if (arg == "--crf") options.film.crf = int(parseWhole(arg, value(arg), 0, 51));
    else if (arg == "--bitrate") options.film.bitrate = film::parseBitrate(value(arg));
    else if (arg == "--pix-fmt") options.film.pixelFormat = value(arg);
    else if (arg == "--full-range") options.film.fullRange = true;
    else if (options.mode == Mode::Encode && !arg.starts_with("-")) {  // encode's FOLDER
      if (!options.sequence.empty())
        throw Error(fmt::format("encode takes one FOLDER, not both {} and {}.", options.sequence, arg));
      options.sequence = arg;
    }
    else if (arg == "--list-devices") options.mode = Mode::ListDevices;
    else if (arg == "--list-scenes") options.mode = Mode::ListScenes;
    else if (arg == "--list-monitors") options.mode = Mode::ListMonitors;
    else if (arg == "--list-params") {
      options.mode = Mode::ListParams;
      if (i + 1 < argc && argv[i + 1][0] != '-') {  // the optional SCENE
        options.listParams = argv[++i];
        if (!findScene(options.listParams)) throw Error(unknownScene(options.listParams));
      }
    }
    else if (arg == "--help" || arg == "-h") options.mode = Mode::Help;
    else if (arg == "--version") options.mode = Mode::Version;
    else throw Error(fmt::format("Unknown option '{}'; see vitrine --help.", arg));
  }
  checkFlagsApply(given, options.mode);
  auto isGiven = [&](std::string_view flag) {
    return std::any_of(given.begin(), given.end(), [&](const FlagRule* rule) { return rule->name == flag; });
  };
  if (options.mode == Mode::Headless && options.out.empty())
    throw Error("--headless needs --out FILE.exr (or FILE.png).");
  if (options.mode == Mode::Bench && options.out.empty()) throw Error("bench needs --json FILE.");
  if (options.mode == Mode::Headless && options.scene.empty()) throw Error("--headless needs --scene NAME.");
  if (options.mode == Mode::Headless && !imageFormatFromName(options.out))
    throw Error(fmt::format("--out writes .exr (linear half float) or .png (8-bit sRGB), not '{}'.", options.out));
  if (options.span && !options.monitor.empty())
    throw Error("--span covers every monitor with one window: drop --monitor.");
  if (options.mode == Mode::Record) {
    if (options.scene.empty()) throw Error("record needs --scene NAME.");
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
      for (const std::string_view flag : kFilmFlags)
        if (isGiven(flag))
          throw Error(fmt::format("{} is for a film: --out NAME.mp4, .mov or .mkv, not the folder {}.", flag, options.out));
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
    std::string ext = std::filesystem::path(options.audioOut).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".wav") throw Error(fmt::format("--audio-out writes WAV: name it FILE.wav, not '{}'.", options.audioOut));
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
