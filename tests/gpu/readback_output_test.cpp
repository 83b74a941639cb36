// A published output (host/present/readback_output.h) reads its frames back without waiting: each frame
// handed to its sink is the frame the headless path renders for the same moment, warp included, as the
// display's 8-bit sRGB bytes; the sink asking another size gets frames of that size; and a copy that
// finds every read-back buffer still in flight is skipped, not waited for.
#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <vector>

#include "gpu/check.h"
#include "gpu/frame_resources.h"
#include "gpu/readback_ring.h"
#include "gpu/sync_objects.h"
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

// Four frames' copies behind a gate the host opens later (a GPU that has not finished them): three take
// the three buffers, the fourth finds them all in flight and is skipped at once; once the GPU is done,
// the newest copy is handed over and the two older ones are counted as superseded.
TEST_F(ReadbackOutputTest, ACopyFindingEveryBufferInFlightIsSkippedNotWaitedFor) {
  gpu::FrameResources resources(device());
  gpu::ReadbackRing ring(device(), resources, 4 * 4 * 4, 3, "ring test");
  gpu::ImageDesc desc;
  desc.extent = {4, 4, 1};
  desc.format = VK_FORMAT_R8G8B8A8_UNORM;
  desc.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  gpu::Image image(device(), desc, "ring source");
  VkSemaphoreTypeCreateInfo timeline{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO, nullptr, VK_SEMAPHORE_TYPE_TIMELINE, 0};
  const VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, &timeline, 0};
  VkSemaphore gate = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSemaphore(device(), &info, nullptr, &gate));
  const gpu::Unique<VkCommandPool> pool = gpu::createCommandPool(device(), 0, "ring test pool");
  std::vector<VkCommandBuffer> cmds(4);
  const VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool,
                                          VK_COMMAND_BUFFER_LEVEL_PRIMARY, 4};
  VK_CHECK(vkAllocateCommandBuffers(device(), &alloc, cmds.data()));
  int recorded = 0;
  for (int i = 0; i < 4; ++i) {
    const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                         VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmds[i], &begin));
    image.use(cmds[i], gpu::use::TransferDst);
    const VkClearColorValue grey{{0.5f, 0.5f, 0.5f, 1.0f}};
    const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmds[i], image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &grey, 1, &all);
    recorded += ring.record(cmds[i], image, double(i)) ? 1 : 0;
    VK_CHECK(vkEndCommandBuffer(cmds[i]));
    const VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, nullptr, gate, 1,
                                     VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0};
    device().submit({cmds[i], std::span(&wait, 1), {}});
    ring.submitted(device().lastSubmitted());
  }
  EXPECT_EQ(recorded, 3);
  EXPECT_TRUE(ring.full());
  EXPECT_FALSE(ring.poll()) << "nothing has finished yet";
  const VkSemaphoreSignalInfo open{VK_STRUCTURE_TYPE_SEMAPHORE_SIGNAL_INFO, nullptr, gate, 1};
  VK_CHECK(vkSignalSemaphore(device(), &open));
  device().waitIdle();
  const auto copy = ring.poll();
  ASSERT_TRUE(copy);
  EXPECT_EQ(copy->tag, 2.0);
  EXPECT_EQ(copy->superseded, 2u) << "the copies of frames 0 and 1 gave way to frame 2's; frame 3 was never copied";
  EXPECT_NEAR(int(uint8_t(copy->bytes[0])), 128, 1);
  EXPECT_FALSE(ring.full());
  vkDestroySemaphore(device(), gate, nullptr);
}

}  // namespace
}  // namespace vitrine::test
