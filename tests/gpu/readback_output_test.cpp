// A published output (host/present/readback_output.h) reads its frames back without waiting: each frame
// handed to its sink is the frame the headless path renders for the same moment, warp included, as the
// display's 8-bit sRGB bytes; the sink asking another size gets frames of that size.
#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <vector>

#include "host/offline/offscreen.h"
#include "host/present/readback_output.h"
#include "image/image_io.h"
#include "support/gpu_test.h"

namespace vitrine::test {
namespace {

struct Received {
  std::vector<uint8_t> bytes;
  uint32_t width, height, stride;
  double time;
};

class KeepingSink final : public host::FrameSink {
 public:
  explicit KeepingSink(std::map<uint64_t, Received>& frames) : frames_(frames) {}
  void frame(const host::PublishedFrame& frame) override {
    const auto* bytes = reinterpret_cast<const uint8_t*>(frame.bytes.data());
    frames_[frame.index] = {std::vector<uint8_t>(bytes, bytes + frame.bytes.size()), frame.width, frame.height,
                            frame.stride, frame.time};
  }
  std::optional<VkExtent2D> wantedExtent() const override { return wanted; }
  host::Output::Health health() const override { return {.kind = "test", .frames = uint64_t(frames_.size())}; }
  std::optional<VkExtent2D> wanted;

 private:
  std::map<uint64_t, Received>& frames_;
};

class ReadbackOutputTest : public GpuTest {
 protected:
  // Renders `count` frames of `scene` at `size` with a published output of the same size and warp; returns
  // the largest difference, in 8-bit steps, between a frame the sink got and the headless frame of its
  // moment, and how many frames the sink got.
  std::pair<int, size_t> compare(const char* scene, VkExtent2D size, const maths::OutputWarp& warp, int count) {
    host::OffscreenConfig config;
    config.scene = scene;
    config.size = size;
    config.startTime = 2.0;
    config.warp = warp;
    host::Offscreen offscreen(device(), config);
    std::map<uint64_t, Received> frames;
    host::ReadbackOutput output(device(), "published", warp, size, std::make_unique<KeepingSink>(frames));
    offscreen.addOutput(output);
    std::map<uint64_t, std::vector<uint8_t>> headless;
    for (int i = 0; i < count; ++i) {
      const uint64_t index = offscreen.frames();
      offscreen.renderFrame();
      headless[index] = srgb8(offscreen.readback());
    }
    offscreen.renderFrame();  // hands the last copy over
    int worst = 0;
    for (const auto& [index, got] : frames) {
      if (!headless.count(index)) continue;  // the extra frame's own copy is still in flight
      EXPECT_EQ(got.width, size.width);
      EXPECT_EQ(got.height, size.height);
      EXPECT_EQ(got.stride, size.width * 4);
      EXPECT_DOUBLE_EQ(got.time, 2.0 + double(index) / 60.0) << "frame " << index;
      const std::vector<uint8_t>& want = headless[index];
      EXPECT_EQ(got.bytes.size(), want.size());
      for (size_t i = 0; i < std::min(got.bytes.size(), want.size()); ++i)
        worst = std::max(worst, std::abs(int(got.bytes[i]) - int(want[i])));
    }
    EXPECT_EQ(output.dropped(), 0u) << "a run that waits for each frame never finds its buffers in flight";
    return {worst, frames.size()};
  }
};

TEST_F(ReadbackOutputTest, EachFrameHandedOverIsTheHeadlessFrameOfItsMoment) {
  const auto [worst, frames] = compare("kifs", {96, 54}, maths::OutputWarp{}, 3);
  EXPECT_GE(frames, 3u);
  EXPECT_LE(worst, 1) << "the GPU's sRGB encoding and the CPU's round alike but for the last step";
}

TEST_F(ReadbackOutputTest, AWarpedOutputIsTheHeadlessFrameThroughTheSameWarp) {
  maths::OutputWarp warp;
  warp.quarterTurns = 1;
  warp.region = {0.25f, 0.0f, 1.0f, 0.75f};
  warp.corners[2] = {0.9f, 0.95f};
  const auto [worst, frames] = compare("calibrate", {64, 96}, warp, 2);
  EXPECT_GE(frames, 2u);
  EXPECT_LE(worst, 1);
}

TEST_F(ReadbackOutputTest, TheSinkAskingAnotherSizeGetsFramesOfThatSize) {
  host::OffscreenConfig config;
  config.scene = "calibrate";
  config.size = {64, 36};
  host::Offscreen offscreen(device(), config);
  std::map<uint64_t, Received> frames;
  auto sink = std::make_unique<KeepingSink>(frames);
  KeepingSink& asking = *sink;
  host::ReadbackOutput output(device(), "published", {}, {64, 36}, std::move(sink));
  offscreen.addOutput(output);
  offscreen.renderFrame();
  asking.wanted = VkExtent2D{40, 30};
  for (int i = 0; i < 3; ++i) offscreen.renderFrame();
  ASSERT_FALSE(frames.empty());
  EXPECT_EQ(frames.begin()->second.width, 64u);
  EXPECT_EQ(frames.rbegin()->second.width, 40u);
  EXPECT_EQ(frames.rbegin()->second.height, 30u);
  EXPECT_EQ(frames.rbegin()->second.bytes.size(), size_t(40 * 30 * 4));
  EXPECT_EQ(output.extent().width, 40u);
}

}  // namespace
}  // namespace vitrine::test
