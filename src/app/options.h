#pragma once
// The command line, parsed into one value. Bad input is a vitrine::Error with a sentence that says
// what was wrong and what would be right; main turns it into a non-zero exit.
#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vitrine {

enum class Mode { Gallery, Headless, Bench, Compare, ListDevices, ListScenes, Help, Version };

struct Options {
  Mode mode = Mode::Gallery;
  std::string scene;                 // empty: the first in the registry (gallery), "all" (bench)
  std::string device;                // --device INDEX|NAME
  bool validation = false;           // --validate, or VITRINE_VALIDATION=1
  bool reducedMotion = false;
  uint32_t seed = 0;
  std::optional<VkExtent2D> size;    // --size WxH (window size in the gallery)
  uint32_t frames = 1;
  double time = 0.0;
  std::string out;                   // --out (headless image) / --json (bench)
  uint32_t warmup = 30;              // bench
  bool fullscreen = false;
  bool vsync = true;
  bool resetSettings = false;        // --reset-settings (gallery)
  std::vector<std::pair<std::string, std::string>> parameters;  // --set key=value
  std::vector<std::string> compare;  // compare REF CANDIDATE
};

Options parseOptions(int argc, const char* const* argv);
VkExtent2D parseSize(const std::string& text);  // "1920x1080"
const char* usage();

}  // namespace vitrine
