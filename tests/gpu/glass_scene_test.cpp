// The glass scene as a whole, rendered headless: the physics it promises, measured on its pictures.
#include "core/error.h"
#include "host/input_script.h"
#include "host/offline/offscreen.h"
#include "support/gpu_test.h"

#include <algorithm>
#include <vector>

namespace vitrine::test {
namespace {

class GlassScene : public GpuTest {
 protected:
  ImageRgba render(params::KeyValues values, uint32_t frames = 4, const char* script = nullptr) {
    host::OffscreenConfig config;
    if (script) config.input = host::parseInputScript(script, "test script");
    config.scene = "glass";
    config.size = {240, 200};
    config.startTime = 0.5;
    config.parameters = {{"background", "checker"}, {"jitter", "off"}};
    config.parameters.insert(config.parameters.end(), values.begin(), values.end());
    host::Offscreen offscreen(device(), config);
    for (uint32_t i = 0; i < frames; ++i) offscreen.renderFrame();
    return offscreen.readback();
  }
};

// The diamond preset as a user first sees it (its own values, nothing of the fixture's), at a small size.
ImageRgba renderPreset(const gpu::Device& device, std::string preset, params::KeyValues values, uint32_t frames = 6,
                       VkExtent2D size = {200, 160}) {
  host::OffscreenConfig config;
  config.scene = "glass";
  config.size = size;
  config.startTime = 1.5;
  config.presets = {std::move(preset)};
  config.parameters = std::move(values);
  host::Offscreen offscreen(device, config);
  for (uint32_t i = 0; i < frames; ++i) offscreen.renderFrame();
  return offscreen.readback();
}

float luminanceOf(const float* p) { return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]; }

// The mean absolute difference over a square of pixels around a normalised point.
double patchDifference(const ImageRgba& a, const ImageRgba& b, float x, float y, int half = 12) {
  double sum = 0.0;
  int count = 0;
  const int cx = int(x * float(a.width)), cy = int(y * float(a.height));
  for (int py = cy - half; py < cy + half; ++py)
    for (int px = cx - half; px < cx + half; ++px)
      for (int c = 0; c < 3; ++c, ++count) sum += std::abs(a.at(px, py)[c] - b.at(px, py)[c]);
  return sum / count;
}

// How coloured the picture is: over a grey checker, every bit of chroma is dispersion.
double meanChroma(const ImageRgba& image) {
  double sum = 0.0;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    const float* p = &image.pixels[i];
    sum += std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
  }
  return sum / double(image.width * image.height);
}

double meanDifference(const ImageRgba& a, const ImageRgba& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(a.pixels[i] - b.pixels[i]);
  return sum / double(a.pixels.size());
}

TEST_F(GlassScene, AVeryLargeAbbeNumberRemovesTheFringesASmallOneMakes) {
  const double dispersive = meanChroma(render({{"abbe", "2"}}));
  const double plain = meanChroma(render({{"abbe", "100"}}));
  EXPECT_GT(dispersive, 0.01) << "V_d = 2 should split the checker's edges into colours";
  EXPECT_LT(plain, dispersive * 0.05) << "V_d = 100 should leave the grey checker grey";
}

TEST_F(GlassScene, GlassOfIndexOneIsInvisible) {
  // Exact Fresnel reflects nothing at eta = 1 and nothing bends: wherever the cubes or the pills are,
  // the picture is the backdrop's (a smooth one: the original's LOD rule blurs a checker at rims).
  const ImageRgba cubes = render({{"optics", "physical"}, {"ior", "1"}, {"shape", "cube"}, {"background", "gradient"}});
  const ImageRgba pills = render({{"optics", "physical"}, {"ior", "1"}, {"shape", "pill"}, {"background", "gradient"}});
  EXPECT_LT(meanDifference(cubes, pills), 2e-4);
  const ImageRgba glass = render({{"optics", "physical"}, {"ior", "1.5"}, {"shape", "cube"}, {"background", "gradient"}});
  EXPECT_GT(meanDifference(cubes, glass), 2e-3) << "real glass must change the picture";
}

TEST_F(GlassScene, DraggingMovesTheShapeUnderTheCursor) {
  // The top-left cube sits at (0.28, 0.30) of a 240x200 view; drag it to the middle.
  const char* drag = "0.5 move 0.28 0.30\n0.52 down\n0.55 move 0.4 0.4\n0.57 move 0.5 0.5\n0.6 up\n";
  const ImageRgba still = render({{"stop_world", "on"}}, 8);
  const ImageRgba dragged = render({{"stop_world", "on"}}, 8, drag);
  EXPECT_GT(patchDifference(still, dragged, 0.5f, 0.5f), 0.02) << "no glass arrived in the middle";
  EXPECT_GT(patchDifference(still, dragged, 0.28f, 0.30f), 0.02) << "the cube did not leave its place";
  EXPECT_LT(patchDifference(still, dragged, 0.72f, 0.70f), 1e-4) << "another cube moved";
}

TEST_F(GlassScene, HoldingZShowsThreeBandsAndReleasingRestores) {
  // Each frame stands alone (alpha 1), so a frame depends only on the settings it was drawn with.
  const params::KeyValues alone{{"history_alpha", "1"}, {"jitter", "on"}};
  const ImageRgba held = render(alone, 3, "0.5 hold z\n");
  params::KeyValues bands = alone;
  bands.push_back({"n", "3"});
  bands.push_back({"jitter", "off"});
  EXPECT_LT(meanDifference(held, render(bands, 3)), 1e-6);
  const ImageRgba released = render(alone, 3, "0.5 hold z\n0.52 release z\n");
  EXPECT_LT(meanDifference(released, render(alone, 3)), 1e-6);
  EXPECT_GT(meanDifference(held, released), 1e-3);
}

// The compute path shades with the same function as the proxies' fragments: the same picture, for
// the turning cubes and for the diamond behind its hull.
TEST_F(GlassScene, TheRasterAndComputePathsAgree) {
  for (const char* shape : {"cube", "diamond"}) {
    const ImageRgba raster = render({{"shape", shape}, {"pass", "raster"}}, 2);
    const ImageRgba compute = render({{"shape", shape}, {"pass", "compute"}}, 2);
    EXPECT_LT(meanDifference(raster, compute), 1e-5) << shape;
    EXPECT_GT(meanChroma(compute), 0.0) << shape;
  }
}

// The diamond's planes and hull are redeclared when its size changes: a stone resized while the scene
// runs is drawn exactly as one made at that size, on both paths. The world stands still and the
// wavelengths do not jitter, so the frames after the change restart the same average.
TEST_F(GlassScene, AResizedDiamondIsDrawnAsOneMadeAtThatSize) {
  for (const char* pass : {"compute", "raster"}) {
    const auto run = [&](std::vector<const char*> sizes) {
      host::OffscreenConfig config;
      config.scene = "glass";
      config.size = {160, 120};
      config.startTime = 0.5;
      config.parameters = {{"background", "checker"}, {"jitter", "off"}, {"shape", "diamond"},
                           {"stop_world", "on"},      {"pass", pass}};
      host::Offscreen offscreen(device(), config);
      for (const char* size : sizes) {
        EXPECT_EQ(offscreen.renderer().applyParameters({{"diamond_size", size}}), "");
        for (int frame = 0; frame < 2; ++frame) offscreen.renderFrame();
      }
      return offscreen.readback();
    };
    const ImageRgba resized = run({"560", "300"});
    EXPECT_EQ(meanDifference(resized, run({"300"})), 0.0) << pass;
    EXPECT_GT(meanDifference(resized, run({"560"})), 1e-3) << pass << ": the size changed nothing";
  }
}

// The diamond preset's frame measured the way a viewer judges it. The stone's pixels are those the
// facet-colour debug view changes; white: every channel near full (brilliance); fire: bright and
// strongly coloured.
struct StoneMeasures {
  double mean = 0.0, stoneShare = 0.0, white = 0.0, fire = 0.0;  // white and fire: shares of the stone
};

StoneMeasures measureDiamond(const gpu::Device& device, const char* optics, VkExtent2D size) {
  const ImageRgba frame = renderPreset(device, "diamond", {{"optics", optics}}, 6, size);
  const ImageRgba facets = renderPreset(device, "diamond", {{"optics", optics}, {"diamond_debug", "facets"}}, 6, size);
  StoneMeasures m;
  int stone = 0, white = 0, fire = 0;
  for (size_t i = 0; i < frame.pixels.size(); i += 4) {
    const float* p = &frame.pixels[i];
    m.mean += luminanceOf(p);
    if (std::abs(p[0] - facets.pixels[i]) + std::abs(p[1] - facets.pixels[i + 1]) +
            std::abs(p[2] - facets.pixels[i + 2]) < 0.05f)
      continue;
    ++stone;
    const float hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
    if (lo > 0.85f) ++white;
    if (hi > 0.5f && hi - lo > 0.5f * hi) ++fire;
  }
  const double pixels = double(frame.width) * frame.height;
  m.mean /= pixels;
  m.stoneShare = stone / pixels;
  m.white = double(white) / std::max(stone, 1);
  m.fire = double(fire) / std::max(stone, 1);
  return m;
}

// The headline: the diamond in its studio is bright, and its stone throws white brilliance and coloured
// fire, in both optics. Measured on lavapipe at 200x160: mean 0.47 / 0.44 (seed / physical), stone 14 %
// of the frame, white 25 % / 21 % of it, fire 4.5 % / 6.6 %. Before the studio (Blender's `studio`
// world, the stone 400 across): mean 0.029 / 0.015, stone 7.3 %, white 0 / 1.1 %, fire 0 / 1.4 %.
TEST_F(GlassScene, TheDiamondSparklesWithWhiteAndColouredFireInBothOptics) {
  for (const char* optics : {"seed", "physical"}) {
    const StoneMeasures m = measureDiamond(device(), optics, {200, 160});
    RecordProperty(std::string(optics) + "_mean", std::to_string(m.mean));
    EXPECT_GT(m.mean, 0.25) << optics << ": the studio should be bright";
    EXPECT_GT(m.stoneShare, 0.08) << optics << ": the stone should fill a sensible part of the frame";
    EXPECT_GT(m.white, 0.04) << optics << ": too little white brilliance";
    EXPECT_GT(m.fire, 0.03) << optics << ": too little coloured fire";
  }
}

// Seed optics' diamond throws nearly as much fire as physical optics' (at 320x180, lavapipe: 4.6 % of
// the stone against 6.2 %). With the original's lean of 0.2 and its grey fallback for trapped light it
// threw 2.6 %, 42 % of physical's: a stone of grey glass with few coloured sparks.
TEST_F(GlassScene, SeedOpticsDiamondThrowsNearlyPhysicalOpticsFire) {
  const StoneMeasures seed = measureDiamond(device(), "seed", {320, 180});
  const StoneMeasures physical = measureDiamond(device(), "physical", {320, 180});
  RecordProperty("seed_fire", std::to_string(seed.fire));
  RecordProperty("physical_fire", std::to_string(physical.fire));
  EXPECT_GT(physical.fire, 0.04) << "physical optics' diamond lost its fire";
  EXPECT_GT(seed.fire, 0.6 * physical.fire) << "seed " << seed.fire << " against physical " << physical.fire;
}

// Turning the environment on with its defaults shows the lit studio, not a dark corner of it.
TEST_F(GlassScene, TheEnvironmentsDefaultsFaceTheLight) {
  const ImageRgba frame = render({{"environment", "on"}, {"shape", "diamond"}}, 2);
  double mean = 0.0;
  for (size_t i = 0; i < frame.pixels.size(); i += 4) mean += luminanceOf(&frame.pixels[i]);
  EXPECT_GT(mean / double(frame.width * frame.height), 0.3);
}

// A bad background is refused when set, with the value named: a misspelt choice, no such file, a device.
TEST_F(GlassScene, ABackgroundThatNamesNothingIsRefusedByName) {
  for (const char* value : {"chcker", "/nonexistent.png", "/dev/zero"}) {
    host::OffscreenConfig config;
    config.scene = "glass";
    config.size = {16, 16};
    config.parameters = {{"background", value}};
    try {
      host::Offscreen offscreen(device(), config);
      ADD_FAILURE() << value << " was accepted";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(value), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace vitrine::test
