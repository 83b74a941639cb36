#include "app/options.h"

#include "core/error.h"

#include <charconv>
#include <cstdlib>
#include <fmt/format.h>
#include <string_view>

namespace vitrine {
namespace {

template <typename T>
T parseNumber(std::string_view flag, std::string_view text) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    throw Error(fmt::format("{} expects a number, not '{}'.", flag, text));
  return value;
}

}  // namespace

const char* usage() {
  return R"(Vitrine: a gallery of real-time GPU pieces.

  vitrine [--scene NAME] [--size WxH] [--fullscreen] [--no-vsync] [--device INDEX|NAME]
          [--reduced-motion] [--seed S] [--validate]
  vitrine --headless --scene NAME [--size WxH] [--frames N] [--time SECONDS] [--seed S]
          [--set KEY=VALUE]... --out FILE.exr|FILE.png
  vitrine bench --scene NAME|all [--size WxH] [--frames N] [--warmup N] [--set KEY=VALUE]... --json FILE
  vitrine compare REFERENCE.exr CANDIDATE.exr
  vitrine --list-devices | --list-scenes | --help | --version

Gallery keys: 1-9 switch scene, Tab hides the UI, V toggles vsync, F11 fullscreen, F12 screenshot, Esc quits.
Headless frame k shows time SECONDS + k/60; the last frame is written.
)";
}

VkExtent2D parseSize(const std::string& text) {
  const auto x = text.find('x');
  if (x == std::string::npos) throw Error(fmt::format("--size expects WIDTHxHEIGHT such as 1920x1080, not '{}'.", text));
  const auto width = parseNumber<uint32_t>("--size", std::string_view(text).substr(0, x));
  const auto height = parseNumber<uint32_t>("--size", std::string_view(text).substr(x + 1));
  if (width == 0 || height == 0) throw Error(fmt::format("--size must be at least 1x1, not '{}'.", text));
  return {width, height};
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
  } else if (argc > 1 && std::string_view(argv[1]) == "compare") {
    options.mode = Mode::Compare;
    for (i = 2; i < argc; ++i) options.compare.emplace_back(argv[i]);
    if (options.compare.size() != 2) throw Error("compare expects two EXR files: REFERENCE CANDIDATE.");
    return options;
  }
  auto value = [&](std::string_view flag) -> std::string {
    if (i + 1 >= argc) throw Error(fmt::format("{} needs a value; see vitrine --help.", flag));
    return argv[++i];
  };
  for (; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--headless") options.mode = Mode::Headless;
    else if (arg == "--scene") options.scene = value(arg);
    else if (arg == "--device") options.device = value(arg);
    else if (arg == "--validate") options.validation = true;
    else if (arg == "--reduced-motion") options.reducedMotion = true;
    else if (arg == "--seed") options.seed = parseNumber<uint32_t>(arg, value(arg));
    else if (arg == "--size") options.size = parseSize(value(arg));
    else if (arg == "--frames") {
      options.frames = parseNumber<uint32_t>(arg, value(arg));
      if (options.frames == 0) throw Error("--frames must be at least 1.");
    } else if (arg == "--time") options.time = parseNumber<double>(arg, value(arg));
    else if (arg == "--out" || arg == "--json") options.out = value(arg);
    else if (arg == "--warmup") options.warmup = parseNumber<uint32_t>(arg, value(arg));
    else if (arg == "--fullscreen") options.fullscreen = true;
    else if (arg == "--no-vsync") options.vsync = false;
    else if (arg == "--set") {
      const std::string kv = value(arg);
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) throw Error(fmt::format("--set expects KEY=VALUE, not '{}'.", kv));
      options.parameters.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    } else if (arg == "--list-devices") options.mode = Mode::ListDevices;
    else if (arg == "--list-scenes") options.mode = Mode::ListScenes;
    else if (arg == "--help" || arg == "-h") options.mode = Mode::Help;
    else if (arg == "--version") options.mode = Mode::Version;
    else throw Error(fmt::format("Unknown option '{}'; see vitrine --help.", arg));
  }
  if (options.mode == Mode::Headless && options.out.empty())
    throw Error("--headless needs --out FILE.exr (or FILE.png).");
  if (options.mode == Mode::Bench && options.out.empty()) throw Error("bench needs --json FILE.");
  if (options.mode == Mode::Headless && options.scene.empty()) throw Error("--headless needs --scene NAME.");
  return options;
}

}  // namespace vitrine
