// The neon scene as a whole, rendered headless on small frames: what its pictures promise, measured -
// tubes that are many, coloured and not white at any density, motion that is a function of simulation
// time only (a paused frame stands, a recording's finer steps draw the same tube), and tubes in a
// still field.
#include "support/gpu_test.h"
#include "neon_render.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <cmath>
#include <cstdio>
#include <vector>

namespace vitrine::test {
namespace {

using namespace neon_frames;

// Pixels a tube lights (the frame's brightest channel above `threshold`, tone-mapped linear light).
size_t litPixels(const ImageRgba& image, float threshold) {
  size_t lit = 0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) lit += maxChannel(&image.pixels[i]) > threshold;
  return lit;
}

struct Colours {
  double tubes = 0.0;      // share of the frame the tubes change (the tubes and their glow)
  double saturated = 0.0;  // share of the bright tube pixels that are strongly coloured
  double white = 0.0;      // share of the frame that is blown out to white
};

// `frame` against `facade` (tubeMask), in the tone-mapped linear light the scene writes.
Colours colours(const ImageRgba& frame, const ImageRgba& facade) {
  size_t tube = 0, bright = 0, saturated = 0, white = 0;
  const std::vector<bool> mask = tubeMask(frame, facade);
  for (size_t i = 0; i < mask.size(); ++i) {
    const float* p = &frame.pixels[i * 4];
    white += minChannel(p) > 0.8f;
    if (!mask[i]) continue;
    ++tube;
    const float hi = maxChannel(p), lo = minChannel(p);
    if (hi < 0.35f) continue;
    ++bright;
    saturated += (hi - lo) / hi > 0.6f;
  }
  const double pixels = double(frame.width) * frame.height;
  return {double(tube) / pixels, bright ? double(saturated) / double(bright) : 0.0, double(white) / pixels};
}

class NeonScene : public GpuTest {};

// Default or dense, the tubes read as coloured neon: a fair share of the frame is tube, most of its
// bright pixels strongly coloured, and almost none of the frame white. Measured after the bloom
// (stage bloom: the tubes, their glow and the tone map, without the tint's and vignette's changes),
// at 160x90, 3 s in.
TEST_F(NeonScene, TubesStayColouredAndDistinctAtTheDefaultAndDense) {
  const VkExtent2D size{160, 90};
  const ImageRgba facade = neonRender(device(), {size, 1.0 / 60.0, 1.0 / 60.0, {{"stage", "base"}}});
  for (const char* preset : {"", "dense"}) {
    const std::string name = *preset ? preset : "default";
    std::vector<std::string> presets;
    if (*preset) presets.push_back(preset);
    const ImageRgba frame = neonRender(device(), {size, 1.0 / 60.0, 3.0, {{"stage", "bloom"}}, nullptr, presets});
    const Colours c = colours(frame, facade);
    std::printf("%s: tubes %.3f of the frame, saturated %.3f of their bright pixels, white %.4f of the frame\n",
                name.c_str(), c.tubes, c.saturated, c.white);
    RecordProperty("tubes_" + name, std::to_string(c.tubes));
    RecordProperty("saturated_" + name, std::to_string(c.saturated));
    RecordProperty("white_" + name, std::to_string(c.white));
    EXPECT_GT(c.tubes, 0.03) << name << ": the tubes should be the subject of the frame";
    EXPECT_GT(c.saturated, 0.5) << name << ": the tubes should be saturated neon colours";
    EXPECT_LT(c.white, 0.002) << name << ": the tubes should not blow out to white";
  }
}

// The lower tiers release into fewer chains (tierChains): a full field (the default's 64 chains, the
// autopilot releasing 40 a second) thins out at the low tier, each tube as coloured as before; the
// default's handful of tubes fits under every tier's chains. A tier lowered while the piece runs lets
// the tubes above its chains swim on: the frame after a switch shows as much tube as one that stayed
// high.
TEST_F(NeonScene, LowerTiersThinADenseFieldWithoutCuttingTubes) {
  const VkExtent2D size{160, 90};
  // The tubes' lit pixels at the low tier over the high tier's, 4 s in, with `values`.
  const auto lowOverHigh = [&](params::KeyValues values) {
    size_t lit[2];
    values.push_back({"stage", "tubes"});
    for (int i = 0; const char* tier : {"high", "low"}) {
      params::KeyValues tiered = values;
      tiered.push_back({"tier", tier});
      lit[i++] = litPixels(neonRender(device(), {size, 1.0 / 60.0, 4.0, tiered}), 0.3f);
    }
    return double(lit[1]) / double(lit[0]);
  };
  const double sparse = lowOverHigh({}), full = lowOverHigh({{"autopilot_rate", "40"}});
  std::printf("lit pixels, low over high: default field %.3f, full field %.3f\n", sparse, full);
  // Measured on lavapipe: 1.61 (the 0.4-scale render alone: tubes at their pixel minimum there are
  // wider once scaled up) and 0.75.
  EXPECT_LT(full, 0.8 * sparse) << "half the chains";

  host::OffscreenConfig config;
  config.scene = "neon";
  config.size = size;
  config.parameters = {{"autopilot_rate", "40"}, {"stage", "tubes"}, {"tier", "high"}};
  host::Offscreen switched(device(), config), stayed(device(), config);
  for (int i = 0; i < 240; ++i) switched.renderFrame(), stayed.renderFrame();  // 4 s: every slot taken
  ASSERT_TRUE(params::applyValues(switched.parameters(), {{"tier", "low"}}).empty());
  switched.renderFrame(), stayed.renderFrame();
  const double after = double(litPixels(switched.readback(), 0.3f)) / double(litPixels(stayed.readback(), 0.3f));
  std::printf("the frame after a switch to low: lit pixels %.3f of staying high\n", after);
  // Measured on lavapipe: 1.66, as the default field's 1.61 (the low tier's wider tubes): every tube still drawn.
  EXPECT_GT(after, 0.8 * sparse) << "the tubes above the low tier's chains are still drawn";
}

// One tube released at the start, seen 2.5 s later: drawn in 60 Hz steps (the gallery) and in 240 Hz
// steps (`record --fps 30 --spp 8`), it covers the same pixels within 10 %. Its width is the same in
// both, so the lit area measures its length. With the followers' share per step, the recording's
// tube was about four times shorter.
TEST_F(NeonScene, TubeLengthIsTheSameAtTheGallerysStepAndARecordingsStep) {
  const char* script = "0.00 action release 0 7 10\n";  // near the camera, a wide tube: many pixels
  // A fast head and a slow fade, so that after 2.5 s the tail has long left the release point and the
  // tube's length is the followers' lag times the head's speed.
  const params::KeyValues values{{"stage", "tubes"}, {"chains", "16"},         {"autopilot_idle", "60"},
                                 {"radius", "0.25"}, {"field_strength", "4"}, {"decay", "0.1"}};
  const ImageRgba facade = neonRender(device(), {{240, 135}, 1.0 / 60.0, 1.0 / 60.0, {{"stage", "base"}}});
  const auto tubePixels = [&](double step) {
    const std::vector<bool> mask = tubeMask(neonRender(device(), {{240, 135}, step, 2.5, values, script}), facade);
    return size_t(std::count(mask.begin(), mask.end(), true));
  };
  const size_t gallery = tubePixels(1.0 / 60.0), recording = tubePixels(1.0 / 240.0);
  RecordProperty("gallery_pixels", int(gallery));
  RecordProperty("recording_pixels", int(recording));
  EXPECT_GT(gallery, 40u) << "the tube should be many pixels long";
  EXPECT_NEAR(double(recording) / double(gallery), 1.0, 0.1) << gallery << " px at 60 Hz, " << recording << " at 240 Hz";
}

// The gallery draws frames without simulation steps while paused (and between the steps of a display
// faster than 60 Hz): the picture must stand still. The chains used to move once per drawn frame.
TEST_F(NeonScene, APausedFrameIsIdenticalAfterMoreDrawnFrames) {
  host::OffscreenConfig config;
  config.scene = "neon";
  config.size = {160, 90};
  config.parameters = {{"chains", "256"}};
  host::Offscreen offscreen(device(), config);
  for (int i = 0; i < 45; ++i) offscreen.renderFrame();
  const ImageRgba before = offscreen.readback();
  ASSERT_GT(litPixels(before, 0.3f), 20u) << "tubes to watch";
  for (int i = 0; i < 6; ++i) offscreen.redrawFrame();
  const ImageRgba after = offscreen.readback();
  size_t changed = 0;
  for (size_t i = 0; i < before.pixels.size(); ++i) changed += before.pixels[i] != after.pixels[i];
  EXPECT_EQ(changed, 0u) << "values changed by drawing the paused frame again";
}

// In a still field (field_strength 0) the tubes used to collapse onto their release points and vanish.
TEST_F(NeonScene, AStillFieldStillShowsTubes) {
  const ImageRgba image =
      neonRender(device(), {{240, 135},
                            1.0 / 60.0,
                            1.5,
                            {{"chains", "256"}, {"autopilot_rate", "10"}, {"field_strength", "0"}, {"stage", "tubes"}}});
  const std::vector<bool> mask =
      tubeMask(image, neonRender(device(), {{240, 135}, 1.0 / 60.0, 1.0 / 60.0, {{"stage", "base"}}}));
  EXPECT_GT(double(std::count(mask.begin(), mask.end(), true)) / (240.0 * 135.0), 0.004);
}

// A drag draws one tube along its path: its lit pixels form one connected piece (the drag used to
// release a comb of separate short tubes).
TEST_F(NeonScene, ADragDrawsOneConnectedTube) {
  const char* script =
      "0.00 move 0.2 0.45\n0.00 down\n0.15 move 0.4 0.35\n0.30 move 0.6 0.5\n0.45 move 0.8 0.4\n0.50 up\n";
  const params::KeyValues values{{"stage", "tubes"}, {"chains", "64"}, {"autopilot_idle", "60"}};
  const ImageRgba image = display(neonRender(device(), {{320, 180}, 1.0 / 60.0, 0.55, values, script}));
  const ImageRgba facade =
      display(neonRender(device(), {{320, 180}, 1.0 / 60.0, 1.0 / 60.0, {{"stage", "base"}, {"chains", "64"}}}));
  const std::vector<bool> mask = tubeMask(image, facade);
  const int w = int(image.width), h = int(image.height);
  std::vector<int> label(size_t(w) * h, -1);
  const auto lit = [&](int x, int y) { return bool(mask[size_t(y) * w + x]); };
  int pieces = 0, largest = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!lit(x, y) || label[size_t(y) * w + x] >= 0) continue;
      std::vector<std::pair<int, int>> stack{{x, y}};
      label[size_t(y) * w + x] = pieces;
      int size = 0;
      while (!stack.empty()) {
        const auto [px, py] = stack.back();
        stack.pop_back();
        ++size;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int qx = px + dx, qy = py + dy;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h || !lit(qx, qy) || label[size_t(qy) * w + qx] >= 0) continue;
            label[size_t(qy) * w + qx] = pieces;
            stack.push_back({qx, qy});
          }
      }
      largest = std::max(largest, size);
      if (size > 3) ++pieces;  // a stray pixel or two of aliasing is not a tube
    }
  EXPECT_EQ(pieces, 1) << "the largest piece has " << largest << " pixels";
  EXPECT_GT(largest, 150) << "a tube across much of the frame";
}

// The facade is drawn once a size; an edited facade.comp (hot reload, as the gallery polls each frame)
// shows at the next frame all the same, not only after a resize. The edit paints the lit facade black.
TEST_F(NeonScene, AHotReloadedFacadeShowsAtTheNextFrame) {
  const auto root = std::filesystem::temp_directory_path() / "vitrine-neon-facade-reload";
  std::filesystem::remove_all(root);
  std::filesystem::copy(VITRINE_SHADER_SOURCE_DIR, root, std::filesystem::copy_options::recursive);
  host::OffscreenConfig config;
  config.scene = "neon";
  config.size = {160, 90};
  config.parameters = {{"stage", "base"}};
  config.shaderSources = root;
  host::Offscreen offscreen(device(), config);
  const auto brightness = [](const ImageRgba& image) {
    double sum = 0.0;
    for (size_t i = 0; i < image.pixels.size(); i += 4) sum += maxChannel(&image.pixels[i]);
    return sum / double(image.width * image.height);
  };
  offscreen.renderFrame();
  const double before = brightness(offscreen.readback());

  const auto path = root / "neon/facade.comp";
  std::stringstream text;
  text << std::ifstream(path).rdbuf();
  std::string source = text.str();
  const std::string lit = "imageStore(colour, p, vec4(lit * pc.facadeBrightness, 1.0));";
  const auto at = source.find(lit);
  ASSERT_NE(at, std::string::npos);
  source.replace(at, lit.size(), "imageStore(colour, p, vec4(0.0, 0.0, 0.0, 1.0));");
  std::ofstream(path) << source;
  std::filesystem::last_write_time(path, std::filesystem::file_time_type::clock::now() + std::chrono::seconds(1));
  EXPECT_GE(offscreen.reloadShaders(), 1);

  offscreen.renderFrame();
  const double after = brightness(offscreen.readback());
  std::filesystem::remove_all(root);
  EXPECT_GT(before, 0.02) << "the lit facade shows";
  EXPECT_LT(after, 0.5 * before) << "the edited facade shows at the next frame";
}

}  // namespace
}  // namespace vitrine::test
