// The host's frame resources under the validation layer with synchronisation checks: declared images
// through many resizes with two frames in flight, a history pair carrying last frame's contents (and
// reported invalid after a resize), and deferred deletion leaving nothing behind at device exit.
#include "core/error.h"
#include "gpu/sync_objects.h"
#include "host/scene_renderer.h"
#include "image/image.h"
#include "support/gpu_test.h"
#include "support/frames_in_flight.h"
#include "support/test_scene.h"

#include <array>
#include <cstring>
#include <optional>

namespace vitrine::test {
namespace {

// Counts frames in a history pair: each frame writes previous + 1 (0 + 1 when the history is not
// valid), then copies it into the target. Also declares a ping-pong pair and a mipmapped image with
// initial data, so their creation, uploads and resizes run under validation too.
class CountingScene final : public TestScene {
 public:
  explicit CountingScene(const SceneContext& context)
      : device_(context.device),
        accumulate_(context.programs, "test/accumulate.comp",
                    {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, 8}) {
    constexpr VkImageUsageFlags usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    history_ = context.resources.declare(
        {"count", VK_FORMAT_R16G16B16A16_SFLOAT, usage, gpu::ImageSize::relative(0.5f), 1, gpu::Pairing::History});
    pingPong_ = context.resources.declare(
        {"ping-pong", VK_FORMAT_R16G16B16A16_SFLOAT, usage, gpu::ImageSize::relative(0.25f), 1, gpu::Pairing::PingPong});
    gpu::ImageDecl atlas{"atlas", VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT, gpu::ImageSize::absolute(16, 16),
                         0};
    atlas.initial.assign(16 * 16 * 4, std::byte{200});
    atlas_ = context.resources.declare(std::move(atlas));
  }

  void record(const FrameContext& frame) override {
    const auto pass = frame.pass("count");
    gpu::Image& current = frame.image(history_);
    gpu::Image& previous = frame.resources.previous(history_);
    validFrames_.push_back(frame.resources.historyValid(history_));
    run(frame, previous, current, 1.0f, frame.resources.historyValid(history_));
    // Two steps through the ping-pong pair, each reading what the last wrote.
    for (int i = 0; i < 2; ++i) {
      run(frame, frame.image(pingPong_), frame.resources.previous(pingPong_), 0.0f, true);
      frame.resources.flip(pingPong_);
    }
    frame.transition(frame.image(atlas_), gpu::use::ComputeSample);
    run(frame, current, frame.target, 0.0f, true);
  }

  std::vector<bool> validFrames_;

 private:
  void run(const FrameContext& frame, gpu::Image& source, gpu::Image& destination, float add, bool useSource) {
    frame.transition(source, gpu::use::ComputeSample);
    frame.transition(destination, gpu::use::ComputeWrite);
    accumulate_.bind(frame.cmd);
    accumulate_.push(frame.cmd, gpu::Bindings()
                                    .sampledImage(source.view(),
                                                  device_.sampler(gpu::Device::Filter::Linear,
                                                                  gpu::Device::Address::Clamp),
                                                  gpu::use::ComputeSample.layout)
                                    .storageImage(destination.view()));
    struct {
      float add;
      uint32_t useSource;
    } push{add, useSource ? 1u : 0u};
    accumulate_.constants(frame.cmd, push);
    accumulate_.dispatchOver(frame.cmd, destination.extent2d(), {8, 8});
  }

  const gpu::Device& device_;
  gpu::ComputeProgram accumulate_;
  gpu::ImageHandle history_, pingPong_, atlas_;
};

CountingScene* lastScene = nullptr;
const SceneInfo& kCounting = testSceneInfo(lastScene);

// Two frames in flight, as the gallery runs them, over the counting scene.
class InFlight : public FramesInFlight {
 public:
  explicit InFlight(const gpu::Device& device) : FramesInFlight(device, Assets("/nonexistent")) {
    renderer().setScene(kCounting);
  }
};

class FrameResources : public GpuTest {};

TEST_F(FrameResources, HistoryCarriesLastFrameAndIsClearedOnResize) {
  InFlight run(device());
  for (int i = 0; i < 5; ++i) run.frame({64, 36});
  EXPECT_FLOAT_EQ(run.firstTexel(), 5.0f) << "each frame adds one to last frame's count";
  run.frame({80, 40});  // a resize recreates the pair: cleared, reported invalid, counting restarts
  EXPECT_FLOAT_EQ(run.firstTexel(), 1.0f);
  run.frame({80, 40});
  EXPECT_FLOAT_EQ(run.firstTexel(), 2.0f);
  const std::vector<bool> expected{false, true, true, true, true, false, true};
  EXPECT_EQ(lastScene->validFrames_, expected);
}

TEST_F(FrameResources, ManyResizesWithFramesInFlightAreValidationClean) {
  InFlight run(device());
  for (uint32_t i = 0; i < 60; ++i) run.frame({40 + (i * 7) % 50, 20 + (i * 13) % 40});
  // Nothing waited for the device while resizing: the old images were retired and are being freed
  // as frames finish, so the graveyard stays small rather than growing with every resize.
  EXPECT_LT(device().retiredCount(), 40u);
}

TEST_F(FrameResources, SceneSwitchesRetireTheOldSceneWithoutWaiting) {
  InFlight run(device());
  for (int i = 0; i < 6; ++i) {
    run.frame({48, 32});
    run.renderer().setScene(kCounting);  // a frame of the old scene may still be running
  }
  run.frame({48, 32});
  EXPECT_FLOAT_EQ(run.firstTexel(), 1.0f) << "a new scene's history starts empty";
}

// Its own instance and device, so the device's destruction — where a leaked object is reported — is
// part of the test.
TEST(FrameResourcesExit, DeferredDeletionFreesEverythingByExit) {
  gpu::Instance instance({true, {}});
  {
    gpu::Device device(instance, {});
    {
      InFlight run(device);
      for (uint32_t i = 0; i < 12; ++i) {
        run.frame({32 + i * 4, 24});
        if (i % 4 == 3) run.renderer().setScene(kCounting);
      }
    }
    EXPECT_EQ(device.retiredCount(), 0u) << "the renderer drains what it retired when it goes";
  }
  EXPECT_EQ(instance.validationMessages(), 0) << "no leaked object at vkDestroyDevice, no hazard";
}

}  // namespace
}  // namespace vitrine::test

namespace vitrine::test {
namespace {

class Submission : public GpuTest {};

TEST_F(Submission, ARecordingThatThrowsFreesItsCommandBufferAndTheQueueGoesOn) {
  for (int i = 0; i < 50; ++i)
    EXPECT_THROW(device().submitNow([](VkCommandBuffer) { throw vitrine::Error("recording failed"); }), vitrine::Error);
  const uint64_t before = device().lastSubmitted();
  device().submitNow([](VkCommandBuffer) {});
  EXPECT_EQ(device().lastSubmitted(), before + 1) << "the failed recordings never reached the queue";
  EXPECT_GE(device().completed(), before + 1);
}

TEST_F(Submission, StreamArenaUploadsArriveAndChunksAreReused) {
  gpu::StreamArena arena(device(), 64 * 1024);
  gpu::Buffer target(device(), 4096, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                     gpu::MemoryUse::Device, "upload target");
  gpu::Buffer readback(device(), 4096, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "upload readback");
  for (uint32_t frame = 0; frame < 40; ++frame) {
    std::vector<uint32_t> values(1024, frame * 7 + 1);
    device().submitNow([&](VkCommandBuffer cmd) {
      gpu::uploadBuffer(cmd, arena, target, 0, std::as_bytes(std::span(values)), gpu::use::TransferSrcBuffer);
      for (int i = 0; i < 8; ++i) arena.allocate(6000);  // per-frame uniform blocks
      readback.use(cmd, gpu::use::TransferDstBuffer);
      const VkBufferCopy copy{0, 0, 4096};
      vkCmdCopyBuffer(cmd, target.handle(), readback.handle(), 1, &copy);
      readback.use(cmd, gpu::use::HostReadBuffer);
    });
    readback.invalidate();
    ASSERT_EQ(readback.view<const uint32_t>()[1023], frame * 7 + 1) << "frame " << frame;
  }
  // About 53 KB a frame, finished before the next: one or two chunks cycle, none is added per frame.
  EXPECT_LE(arena.chunkCount(), 2u);
}

// Bindings hold values only: a copy outlives the original and pushes the same descriptors.
TEST_F(Submission, CopiedBindingsStayValid) {
  gpu::ProgramLibrary programs(device());
  gpu::ComputeProgram accumulate(programs, "test/accumulate.comp",
                                 {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, 8});
  gpu::ImageDesc desc;
  desc.extent = {8, 8, 1};
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  gpu::Image source(device(), desc, "source"), destination(device(), desc, "destination");
  std::optional<gpu::Bindings> copy;
  {
    auto original = std::make_unique<gpu::Bindings>();
    original->sampledImage(source.view(), device().sampler(gpu::Device::Filter::Nearest, gpu::Device::Address::Clamp),
                           gpu::use::ComputeSample.layout)
        .storageImage(destination.view());
    copy = *original;
    std::memset(static_cast<void*>(original.get()), 0xAB, sizeof(gpu::Bindings));  // the original is gone
  }
  gpu::Buffer readback(device(), 8 * 8 * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "readback");
  device().submitNow([&](VkCommandBuffer cmd) {
    source.use(cmd, gpu::use::ComputeSample);
    destination.use(cmd, gpu::use::ComputeWrite);
    accumulate.bind(cmd);
    accumulate.push(cmd, *copy);
    const struct {
      float add;
      uint32_t useSource;
    } push{3.0f, 0u};
    accumulate.constants(cmd, push);
    accumulate.dispatchOver(cmd, VkExtent2D{8, 8}, {8, 8});
    gpu::recordReadback(cmd, destination, readback);
  });
  readback.invalidate();
  EXPECT_FLOAT_EQ(imageFromHalves(8, 8, readback.view<const uint16_t>()).pixels[0], 3.0f);
}

}  // namespace
}  // namespace vitrine::test

namespace vitrine::test {
namespace {

// An image whose initial texels are not uploaded yet holds garbage: using it is an error, not noise
// (a scene that redeclared its lattice while recording read undefined memory before this check).
TEST_F(Submission, AnImageIsNotUsableBeforeItsInitialContentsAreWritten) {
  gpu::FrameResources resources(device());
  gpu::ImageDecl decl{"seeded", VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT, gpu::ImageSize::absolute(4, 4)};
  decl.initial.assign(4 * 4 * 4, std::byte{7});
  const gpu::ImageHandle handle = resources.declare(decl);
  EXPECT_THROW(resources.current(handle), Error);
  gpu::StreamArena arena(device());
  device().submitNow([&](VkCommandBuffer cmd) { resources.beginFrame(cmd, arena); });
  EXPECT_NO_THROW(resources.current(handle));
  resources.redeclare(handle, decl);
  EXPECT_THROW(resources.current(handle), Error) << "a redeclared image waits for the next frame's upload";
  device().waitIdle();
}

}  // namespace
}  // namespace vitrine::test
