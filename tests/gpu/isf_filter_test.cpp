// ISF filters after a native scene and ISF transitions between two, rendered headless on the device
// with the validation layer watching. ISF computes on display values (docs/ISF.md), so what a filter
// promises is measured on the sRGB-encoded picture: an inversion gives 1 - x of it.
#include "host/filters/filter_chain.h"
#include "host/filters/isf_transition.h"
#include "host/offline/offscreen.h"
#include "host/scene_renderer.h"
#include "image/image.h"
#include "isf_twins.h"
#include "scenes/pieces/piece_catalogue.h"
#include "scenes/pieces/piece_scene.h"
#include "support/gpu_test.h"
#include "unit/isf_test_files.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace vitrine::test {
namespace {

using isf::test::isfFile;

constexpr VkExtent2D kSize{320, 180};

float displayValue(float linear) { return linearToSrgb(std::clamp(linear, 0.0f, 1.0f)); }

// The mean over every pixel and colour channel of |f(a's display value) - b's display value|.
double meanError(const ImageRgba& a, const ImageRgba& b, const std::function<float(float)>& f) {
  double sum = 0.0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) sum += std::abs(f(displayValue(a.at(x, y)[c])) - displayValue(b.at(x, y)[c]));
  return sum / (double(a.width) * a.height * 3);
}
float same(float v) { return v; }

// The spread of a picture's display values: a test picture that is one flat colour proves nothing.
double spread(const ImageRgba& image) {
  float lo = 1.0f, hi = 0.0f;
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    lo = std::min(lo, displayValue(image.pixels[i])), hi = std::max(hi, displayValue(image.pixels[i]));
  }
  return hi - lo;
}

class IsfFilters : public GpuTest {
 protected:
  // Frame `frames` of `scene` with `filters` after it.
  ImageRgba render(const std::string& scene, std::vector<host::FilterSpec> filters, uint32_t frames = 2) {
    host::OffscreenConfig config;
    config.scene = scene;
    config.size = kSize;
    config.filters = std::move(filters);
    host::Offscreen offscreen(device(), config);
    for (uint32_t i = 0; i < frames; ++i) offscreen.renderFrame();
    return offscreen.readback();
  }
  static host::FilterSpec filter(const std::string& file, params::KeyValues values = {}) {
    return {isfFile(file), std::move(values)};
  }
};

TEST_F(IsfFilters, AnInversionAfterANativeSceneIsOneMinusItsPicture) {
  const ImageRgba plain = render("calibrate", {});
  const ImageRgba inverted = render("calibrate", {filter("filter_invert.fs")});
  ASSERT_GT(spread(plain), 0.5);
  const double error = meanError(plain, inverted, [](float v) { return 1.0f - v; });
  std::printf("calibrate inverted: mean |(1 - x) - filtered| %.5f (plain against filtered: %.5f)\n", error,
              meanError(plain, inverted, same));
  EXPECT_LT(error, 0.01);
}

TEST_F(IsfFilters, AFiltersParameterChangesThePicture) {
  const ImageRgba plain = render("calibrate", {});
  const ImageRgba none = render("calibrate", {filter("filter_invert.fs", {{"amount", "0"}})});
  const ImageRgba half = render("calibrate", {filter("filter_invert.fs", {{"amount", "0.5"}})});
  const double unchanged = meanError(plain, none, same);
  const double halfway = meanError(plain, half, [](float) { return 0.5f; });
  std::printf("amount 0: mean error against the plain picture %.5f; amount 0.5: against grey %.5f\n", unchanged, halfway);
  EXPECT_LT(unchanged, 0.01);
  EXPECT_LT(halfway, 0.01);
}

// Inverting then halving gives (1 - x) / 2; halving then inverting 1 - x / 2.
TEST_F(IsfFilters, TheChainsOrderIsTheOrderGiven) {
  const ImageRgba plain = render("calibrate", {});
  const ImageRgba invertFirst = render("calibrate", {filter("filter_invert.fs"), filter("filter_gain.fs")});
  const ImageRgba gainFirst = render("calibrate", {filter("filter_gain.fs"), filter("filter_invert.fs")});
  const double a = meanError(plain, invertFirst, [](float v) { return 0.5f * (1.0f - v); });
  const double b = meanError(plain, gainFirst, [](float v) { return 1.0f - 0.5f * v; });
  const double crossed = meanError(plain, invertFirst, [](float v) { return 1.0f - 0.5f * v; });
  std::printf("invert, gain: %.5f from (1 - x) / 2; gain, invert: %.5f from 1 - x / 2; crossed: %.5f\n", a, b, crossed);
  EXPECT_LT(a, 0.01);
  EXPECT_LT(b, 0.01);
  EXPECT_GT(crossed, 0.1);
}

// The filter stretches the picture's lower half over all of it: row r of what it shows is row
// 90 + (r + 0.5) / 2 - 0.5 of the 180-row picture (sampled between rows). Flipped the wrong way on the
// way in or out, the upper half would show: row (r + 0.5) / 2 - 0.5.
TEST_F(IsfFilters, AFilterSeesThePictureTheRightWayUp) {
  const ImageRgba plain = render("calibrate", {});
  const ImageRgba stretched = render("calibrate", {filter("filter_lower_half.fs")});
  // The mean difference from the plain picture's rows `first`.. stretched twice, between rows linearly.
  const auto errorFrom = [&](float first) {
    double sum = 0.0;
    for (uint32_t y = 0; y < kSize.height; ++y) {
      const float row = std::clamp(first + (float(y) + 0.5f) / 2.0f - 0.5f, 0.0f, float(kSize.height - 1));
      const uint32_t above = uint32_t(row), below = std::min(above + 1, kSize.height - 1);
      const float t = row - float(above);
      for (uint32_t x = 0; x < kSize.width; ++x)
        for (int c = 0; c < 3; ++c) {
          const float want = (1.0f - t) * displayValue(plain.at(x, above)[c]) + t * displayValue(plain.at(x, below)[c]);
          sum += std::abs(want - displayValue(stretched.at(x, y)[c]));
        }
    }
    return sum / (double(kSize.width) * kSize.height * 3);
  };
  const double lower = errorFrom(float(kSize.height) / 2.0f), upper = errorFrom(0.0f);
  std::printf("the lower half stretched: mean error %.4f; against the upper half stretched %.4f\n", lower, upper);
  EXPECT_LT(lower, 0.01);
  EXPECT_GT(upper, 0.05);
}

// An ISF generator as a scene (gl3_style.fs: grey cells), then an inversion after it.
TEST_F(IsfFilters, AnInversionAfterAnIsfGeneratorIsOneMinusItsPicture) {
  const std::filesystem::path file = isfFile("gl3_style.fs");
  pieces::Piece* piece = pieces::findPieceByPath(file);
  if (!piece) {
    const auto added = pieces::addPieces(std::vector{file}, true);
    pieces::addPieceFactories(added);
    piece = added.front();
  }
  const ImageRgba plain = render(piece->name, {});
  const ImageRgba inverted = render(piece->name, {filter("filter_invert.fs")});
  ASSERT_GT(spread(plain), 0.5);
  const double error = meanError(plain, inverted, [](float v) { return 1.0f - v; });
  std::printf("%s inverted: mean |(1 - x) - filtered| %.5f\n", piece->name.c_str(), error);
  EXPECT_LT(error, 0.01);
}

TEST_F(IsfFilters, AFilterRefusesAFileThatIsNotOne) {
  host::OffscreenConfig config;
  config.scene = "calibrate";
  config.size = {32, 18};
  config.filters = {filter("transition_mix.fs")};
  EXPECT_THROW(host::Offscreen(device(), config), Error);
  config.filters = {filter("filter_invert.fs", {{"amount", "7"}})};
  EXPECT_THROW(host::Offscreen(device(), config), Error);
}

// A transition between two scenes at progress 0, 0.5 and 1: the start frame, their mix on display
// values (transition_mix.fs), the end frame.
TEST_F(IsfFilters, ATransitionAtZeroHalfAndOneIsTheStartTheMixAndTheEnd) {
  Assets assets = Assets::locate();
  gpu::ProgramLibrary programs(device());
  host::SceneRenderer outgoing(device(), programs, assets, 1), incoming(device(), programs, assets, 1);
  outgoing.setScene(*findScene("calibrate"));
  incoming.setScene(*findScene("kifs"));
  outgoing.scene().update(FrameInput{});
  incoming.scene().update(FrameInput{});
  host::IsfTransition transition(device(), programs, isfFile("transition_mix.fs"));
  gpu::ImageDesc desc;
  desc.extent = {kSize.width, kSize.height, 1};
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  gpu::Image output(device(), desc, "transition output");
  gpu::Buffer staging(device(), size_t(kSize.width) * kSize.height * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      gpu::MemoryUse::Readback, "readback");
  const auto shown = [&](const host::Crossfade& fade, host::SceneRenderer& renderer, bool withIncoming) {
    device().submitNow([&](VkCommandBuffer cmd) {
      if (withIncoming) incoming.recordTarget(cmd, 0, FrameInput{}, kSize);
      output.discard();
      renderer.record(cmd, 0, FrameInput{},
                      host::BlitDestination{output.handle(), kSize, output.lastUse(), gpu::use::TransferSrc, output.view()},
                      fade);
      output.assumeUse(gpu::use::TransferSrc);
      gpu::recordReadback(cmd, output, staging);
    });
    staging.invalidate();
    return imageFromHalves(kSize.width, kSize.height, staging.view<const uint16_t>());
  };
  const ImageRgba start = shown({}, outgoing, false), end = shown({}, incoming, false);
  ASSERT_GT(meanError(start, end, same), 0.05);  // two pictures a transition can be told apart between
  const ImageRgba at0 = shown({&incoming.target(), 0.0f, &transition}, outgoing, true);
  const ImageRgba at1 = shown({&incoming.target(), 1.0f, &transition}, outgoing, true);
  const ImageRgba half = shown({&incoming.target(), 0.5f, &transition}, outgoing, true);
  const double e0 = meanError(start, at0, same), e1 = meanError(end, at1, same);
  double eHalf = 0.0;
  for (uint32_t y = 0; y < kSize.height; ++y)
    for (uint32_t x = 0; x < kSize.width; ++x)
      for (int c = 0; c < 3; ++c)
        eHalf += std::abs(0.5f * (displayValue(start.at(x, y)[c]) + displayValue(end.at(x, y)[c])) - displayValue(half.at(x, y)[c]));
  eHalf /= double(kSize.width) * kSize.height * 3;
  // The cross-fade's own mix is in linear light: what the picture would be without the transition.
  double linearMix = 0.0;
  for (uint32_t y = 0; y < kSize.height; ++y)
    for (uint32_t x = 0; x < kSize.width; ++x)
      for (int c = 0; c < 3; ++c)
        linearMix += std::abs(displayValue(0.5f * (start.at(x, y)[c] + end.at(x, y)[c])) - displayValue(half.at(x, y)[c]));
  linearMix /= double(kSize.width) * kSize.height * 3;
  // Dipped through black all the way (dip 1): black half-way, the start and end pictures at either end.
  ASSERT_EQ(transition.applyParameters({{"dip", "1"}}), "");
  const ImageRgba dipped = shown({&incoming.target(), 0.5f, &transition}, outgoing, true);
  const ImageRgba dippedStart = shown({&incoming.target(), 0.0f, &transition}, outgoing, true);
  const double black = meanError(dipped, dipped, [](float) { return 0.0f; });
  const double dippedAt0 = meanError(start, dippedStart, same);
  std::printf("the cross-fade's linear mix against the transition's at 0.5: %.5f; dipped: %.5f from black at 0.5, "
              "%.5f from the start at 0\n",
              linearMix, black, dippedAt0);
  EXPECT_LT(black, 0.01);
  EXPECT_LT(dippedAt0, 0.01);
  std::printf("progress 0 against the start %.5f, 1 against the end %.5f, 0.5 against their mix %.5f (start against "
              "end %.5f)\n",
              e0, e1, eHalf, meanError(start, end, same));
  EXPECT_LT(e0, 0.01);
  EXPECT_LT(e1, 0.01);
  EXPECT_LT(eHalf, 0.01);
  device().waitIdle();
}

// A filter's passes cost no more than the same fragment work written natively: filter_invert.fs after
// the speed field and its native twin (InvertTwin, one pass where the runner has three) draw the same
// picture. With VITRINE_ISF_SPEED=WxH (the GPU machine, 1920x1080) each one's GPU time is printed,
// medians of 240 frames after 60, for docs/PERFORMANCE.md.
TEST_F(IsfFilters, AnInversionDrawsWhatItsNativeTwinDraws) {
  const TwinRun run = twinRun();
  ASSERT_TRUE(run.valid) << std::getenv("VITRINE_ISF_SPEED");
  SpeedTwin* field = nullptr;
  InvertTwin* twin = nullptr;
  const TestSceneEntry& fieldEntry = testScene(field);
  const TestSceneEntry& twinEntry = testScene(twin);
  host::OffscreenConfig isfConfig = twinConfig(run.size);
  isfConfig.filters = {filter("filter_invert.fs")};
  host::Offscreen isf(device(), isfConfig);
  isf.renderer().setScene(fieldEntry.info, fieldEntry.create);
  host::Offscreen native(device(), twinConfig(run.size));
  native.renderer().setScene(twinEntry.info, twinEntry.create);
  const TwinTimes times = timeTwins(isf, native, run, "native filter twin");
  ASSERT_NE(field, nullptr);
  ASSERT_NE(twin, nullptr);
  std::printf("filter speed %ux%u on %s: isf source %.4f ms + isf pass %.4f ms + isf output %.4f ms; native filter "
              "twin %.4f ms\n",
              run.size.width, run.size.height, device().properties().deviceName, times.source, times.pass,
              times.output, times.twin);
  EXPECT_GT(times.pass, 0.0) << "the filter ran";
  const ImageRgba a = isf.readback(), b = native.readback();
  ASSERT_GT(spread(a), 0.3);
  const TwinDifference d = displayDifference(a, b);
  std::printf("filter against its native twin: %.3f (mean) and %.3f (worst) of an 8-bit step\n", d.mean, d.worst);
  EXPECT_LE(d.worst, 1.0);
  EXPECT_LT(d.mean, 0.5);
}

}  // namespace
}  // namespace vitrine::test
