// Golden frames: every case in tests/golden/cases.txt renders headless and must match its EXR under
// the metric of src/image/image_compare.h; every "!" line changes a parameter of a case and must NOT
// match, proving the comparison can fail. VITRINE_UPDATE_GOLDENS=1 rewrites the goldens instead
// (scripts/update-goldens), and only that.
#include "image/image_compare.h"
#include "image/image_io.h"
#include "host/offline/offscreen.h"
#include "scenes/pieces/piece_scene.h"
#include "support/gpu_test.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace vitrine::test {
namespace {

const std::filesystem::path kGoldenDir = VITRINE_GOLDEN_DIR;
const std::filesystem::path kOutputDir = VITRINE_GOLDEN_OUTPUT_DIR;

struct GoldenCase {
  std::string name;
  host::OffscreenConfig config;
  uint32_t frames = 1;
  CompareThresholds thresholds;
  std::vector<std::pair<std::string, std::string>> mutation;  // non-empty: must differ from the golden
};

std::pair<std::string, std::string> splitParameter(const std::string& word) {
  const auto eq = word.find('=');
  return {word.substr(0, eq), eq == std::string::npos ? "" : word.substr(eq + 1)};
}

// "name scene WxH frames time seed [key=value ...]" or "! name key=value ...".
std::vector<GoldenCase> loadCases(bool mutations) {
  std::ifstream in(kGoldenDir / "cases.txt");
  std::map<std::string, GoldenCase> byName;
  std::vector<GoldenCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (first == "!") {
      std::string base, word;
      words >> base;
      GoldenCase mutant = byName.at(base);
      while (words >> word) mutant.mutation.push_back(splitParameter(word));
      mutant.name = base + "_mutated";
      if (mutations) cases.push_back(mutant);
      continue;
    }
    GoldenCase c;
    c.name = first;
    std::string size, word;
    words >> c.config.scene >> size >> c.frames >> c.config.startTime >> c.config.seed;
    // "isf:FILE": a piece, the ISF generator tests/isf/FILE, registered as the program would at start.
    if (c.config.scene.starts_with("isf:")) {
      const std::filesystem::path file = kGoldenDir.parent_path() / "isf" / c.config.scene.substr(4);
      const pieces::Piece* piece = pieces::findPieceByPath(file);
      if (!piece) {
        const auto added = pieces::addPieces(std::vector{file}, true);
        pieces::addPieceFactories(added);
        piece = added.front();
      }
      c.config.scene = piece->name;
    }
    const auto x = size.find('x');
    c.config.size = {uint32_t(std::stoul(size.substr(0, x))), uint32_t(std::stoul(size.substr(x + 1)))};
    while (words >> word) {
      auto parameter = splitParameter(word);
      if (parameter.first == "reduced_motion")  // a host flag, not a scene parameter
        c.config.reducedMotion = parameter.second == "on";
      else if (parameter.first == "preset")  // a scene preset, applied before the other values
        c.config.presets.push_back(parameter.second);
      else if (parameter.first == "input")  // an input script beside cases.txt (held keys, drags)
        c.config.input = host::loadInputScript(kGoldenDir / parameter.second);
      else if (parameter.first == "fail_fraction")  // per-case metric overrides, see cases.txt
        c.thresholds.failFraction = std::stod(parameter.second);
      else if (parameter.first == "hard_limit")
        c.thresholds.hardLimit = std::stof(parameter.second);
      else if (parameter.first == "lowpass")  // the second, block-averaged comparison (cases.txt)
        c.thresholds.block = std::stoi(parameter.second);
      else
        c.config.parameters.push_back(std::move(parameter));
    }
    byName[c.name] = c;
    if (!mutations) cases.push_back(c);
  }
  return cases;
}

// The case's last frame. Only it is compared, so the frames before it are simulated and not drawn
// (FrameContext::draws, as a recording's frames before its range), unless `drawEvery`: the flash guard
// judges each frame against the ones shown before it, so its run shows them all. A scene whose last
// frame depended on the frames drawn before it would fail the guard's bit-for-bit check below.
ImageRgba render(const gpu::Device& device, host::OffscreenConfig config, uint32_t frames,
                 const std::vector<std::pair<std::string, std::string>>& extra, bool drawEvery = false) {
  config.parameters.insert(config.parameters.end(), extra.begin(), extra.end());
  host::Offscreen offscreen(device, config);
  for (uint32_t i = 0; i < frames; ++i) offscreen.renderFrame(1, drawEvery || i + 1 == frames);
  return offscreen.readback();
}

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }

class Golden : public GpuTest, public ::testing::WithParamInterface<GoldenCase> {};
class GoldenMutation : public GpuTest, public ::testing::WithParamInterface<GoldenCase> {};

// The flash guard never alters a frame within WCAG 2.3.1's thresholds (docs/INSTALLATIONS.md): every
// case, rendered again through it, is the same to the last bit as the frame compared with its golden.
// One test, so the plain frame is rendered once for both checks.
TEST_P(Golden, MatchesReferenceAndTheFlashGuardChangesNoBit) {
  const GoldenCase& c = GetParam();
  const ImageRgba image = render(device(), c.config, c.frames, {});
  const auto golden = kGoldenDir / (c.name + ".exr");
  if (const char* update = std::getenv("VITRINE_UPDATE_GOLDENS"); update && std::string(update) == "1") {
    writeImage(golden, image);
    GTEST_SKIP() << "rewrote " << golden;
  }
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing: run scripts/update-goldens";
  const CompareResult result = compareImages(readImage(golden), image, c.thresholds);
  if (!result.passed) {  // leave the evidence where a person can look at it
    std::filesystem::create_directories(kOutputDir);
    writeImage(kOutputDir / (c.name + ".exr"), image);
    writeImage(kOutputDir / (c.name + ".png"), image);
  }
  EXPECT_TRUE(result.passed) << c.name << ": " << result.summary();

  host::OffscreenConfig guarded = c.config;
  guarded.flashGuard = true;
  const ImageRgba shown = render(device(), guarded, c.frames, {}, /*drawEvery=*/true);
  ASSERT_EQ(image.pixels.size(), shown.pixels.size());
  float largest = 0.0f;
  for (size_t i = 0; i < image.pixels.size(); ++i) largest = std::max(largest, std::abs(image.pixels[i] - shown.pixels[i]));
  EXPECT_EQ(largest, 0.0f) << c.name << ": the guard changed a frame within the thresholds";
}

TEST_P(GoldenMutation, ComparisonCatchesTheChange) {
  const GoldenCase& c = GetParam();
  const auto golden = kGoldenDir / (c.name.substr(0, c.name.size() - 8) + ".exr");
  ASSERT_TRUE(std::filesystem::exists(golden)) << golden << " is missing: run scripts/update-goldens";
  const CompareResult result =
      compareImages(readImage(golden), render(device(), c.config, c.frames, c.mutation), c.thresholds);
  EXPECT_FALSE(result.passed) << c.name << " still matches its golden: " << result.summary();
}

std::string caseName(const ::testing::TestParamInfo<GoldenCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Frames, Golden, ::testing::ValuesIn(loadCases(false)), caseName);
INSTANTIATE_TEST_SUITE_P(Frames, GoldenMutation, ::testing::ValuesIn(loadCases(true)), caseName);

}  // namespace
}  // namespace vitrine::test
