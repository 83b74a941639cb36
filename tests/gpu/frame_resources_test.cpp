// The host's frame resources under the validation layer with synchronisation checks: declared images
// through many resizes with two frames in flight, a history pair carrying last frame's contents (and
// reported invalid after a resize), and deferred deletion leaving nothing behind at device exit; then
// declared buffers: initial bytes, clears, sizes that follow the target, pairs and one per frame in flight.
#include "core/error.h"
#include "gpu/buffer_commands.h"
#include "gpu/sync_objects.h"
#include "host/scene_renderer.h"
#include "image/image.h"
#include "shaders/test/accumulate_push.h"
#include "support/gpu_test.h"
#include "support/frames_in_flight.h"
#include "support/test_scene.h"

#include <array>
#include <cstring>
#include <numeric>
#include <optional>
#include <set>

namespace vitrine::test {
namespace {

// Counts frames in a history pair: each frame writes previous + 1 (0 + 1 when the history is not
// valid), then copies it into the target. Also declares a ping-pong pair and a mipmapped image with
// initial data, so their creation, uploads and resizes run under validation too.
class CountingScene final : public TestScene {
 public:
  explicit CountingScene(const SceneContext& context)
      : device_(context.device), accumulate_(context.programs, "test/accumulate.comp") {
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
                                    .sampledImage("source", source.view(),
                                                  device_.sampler(gpu::Device::Filter::Linear,
                                                                  gpu::Device::Address::Clamp),
                                                  gpu::use::ComputeSample.layout)
                                    .storageImage("destination", destination.view()));
    accumulate_.constants(frame.cmd, shader::TestAccumulatePush{.add = add, .useSource = useSource ? 1u : 0u});
    accumulate_.dispatchOver(frame.cmd, destination.extent2d());
  }

  const gpu::Device& device_;
  gpu::ComputeProgram accumulate_;
  gpu::ImageHandle history_, pingPong_, atlas_;
};

CountingScene* lastScene = nullptr;
const TestSceneEntry& kCounting = testScene(lastScene);

// Two frames in flight, as the gallery runs them, over the counting scene.
class InFlight : public FramesInFlight {
 public:
  explicit InFlight(const gpu::Device& device) : FramesInFlight(device, Assets("/nonexistent")) {
    renderer().setScene(kCounting.info, kCounting.create);
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
    run.renderer().setScene(kCounting.info, kCounting.create);  // a frame of the old scene may still be running
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
        if (i % 4 == 3) run.renderer().setScene(kCounting.info, kCounting.create);
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
  gpu::ComputeProgram accumulate(programs, "test/accumulate.comp");
  gpu::ImageDesc desc;
  desc.extent = {8, 8, 1};
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  gpu::Image source(device(), desc, "source"), destination(device(), desc, "destination");
  std::optional<gpu::Bindings> copy;
  {
    auto original = std::make_unique<gpu::Bindings>();
    original
        ->sampledImage("source", source.view(),
                       device().sampler(gpu::Device::Filter::Nearest, gpu::Device::Address::Clamp),
                       gpu::use::ComputeSample.layout)
        .storageImage("destination", destination.view());
    copy = *original;
    std::memset(static_cast<void*>(original.get()), 0xAB, sizeof(gpu::Bindings));  // the original is gone
  }
  gpu::Buffer readback(device(), 8 * 8 * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "readback");
  device().submitNow([&](VkCommandBuffer cmd) {
    source.use(cmd, gpu::use::ComputeSample);
    destination.use(cmd, gpu::use::ComputeWrite);
    accumulate.bind(cmd);
    accumulate.push(cmd, *copy);
    accumulate.constants(cmd, shader::TestAccumulatePush{.add = 3.0f, .useSource = 0u});
    accumulate.dispatchOver(cmd, VkExtent2D{8, 8});
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

namespace vitrine::test {
namespace {

// Declared buffers on their own, with the host's part (creation, resizes, the start of a frame) done
// by hand, and their contents copied back to the CPU.
class DeclaredBuffers : public GpuTest {
 protected:
  static constexpr VkBufferUsageFlags kCopyable = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

  // A buffer the host clears to `value` when it creates it, readable by a copy.
  static gpu::BufferDecl clearedTo(uint32_t value, gpu::BufferSize size) {
    return {.name = "cleared",
            .size = size,
            .usage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
            .clear = true,
            .clearValue = value};
  }
  // What the host does first in every frame: pending uploads and clears.
  void beginFrame(uint32_t slot = 0) {
    device().submitNow([&](VkCommandBuffer cmd) { resources_.beginFrame(cmd, arena_, slot); });
  }
  void fill(gpu::Buffer& buffer, uint32_t value) {
    device().submitNow([&](VkCommandBuffer cmd) { gpu::fillBuffer(cmd, buffer, value, gpu::use::TransferSrcBuffer); });
  }
  // The buffer's 32-bit words as the GPU left them.
  std::vector<uint32_t> words(gpu::Buffer& buffer) {
    gpu::Buffer staging(device(), buffer.size(), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback,
                        "buffer readback");
    device().submitNow([&](VkCommandBuffer cmd) {
      buffer.use(cmd, gpu::use::TransferSrcBuffer);
      staging.use(cmd, gpu::use::TransferDstBuffer);
      const VkBufferCopy region{0, 0, buffer.size()};
      vkCmdCopyBuffer(cmd, buffer.handle(), staging.handle(), 1, &region);
      staging.use(cmd, gpu::use::HostReadBuffer);
    });
    staging.invalidate();
    const auto view = staging.view<const uint32_t>();
    return {view.begin(), view.end()};
  }

  gpu::FrameResources resources_{device()};
  gpu::StreamArena arena_{device()};
};

TEST_F(DeclaredBuffers, AnAbsoluteBufferStartsWithItsInitialBytes) {
  std::vector<uint32_t> values(64);
  std::iota(values.begin(), values.end(), 1000u);
  gpu::BufferDecl decl{.name = "seeded", .size = gpu::BufferSize::absolute(values.size() * 4), .usage = kCopyable};
  decl.initial.resize(values.size() * 4);
  std::memcpy(decl.initial.data(), values.data(), decl.initial.size());
  const gpu::BufferHandle handle = resources_.declare(std::move(decl));
  EXPECT_THROW(resources_.current(handle), Error) << "its bytes arrive as the next frame begins";
  beginFrame();
  EXPECT_EQ(words(resources_.current(handle)), values);
}

TEST_F(DeclaredBuffers, AClearedBufferStartsWithItsClearValue) {
  const gpu::BufferHandle handle = resources_.declare(clearedTo(0xC0FFEEu, gpu::BufferSize::absolute(1024)));
  EXPECT_THROW(resources_.current(handle), Error) << "its clear is recorded as the next frame begins";
  beginFrame();
  EXPECT_EQ(words(resources_.current(handle)), std::vector<uint32_t>(256, 0xC0FFEEu));
}

// 4 bytes a pixel of the target: none before the target's size is known, then a new buffer at each
// new size, cleared again.
TEST_F(DeclaredBuffers, ARelativeBufferIsRecreatedAtTheTargetsNewSizeOnResize) {
  const gpu::BufferHandle handle = resources_.declare(clearedTo(7u, gpu::BufferSize::relative(4)));
  EXPECT_THROW(resources_.current(handle), Error) << "no size before the first resize";
  resources_.resize({16, 8});
  beginFrame();
  const VkBuffer first = resources_.current(handle).handle();
  EXPECT_EQ(resources_.current(handle).size(), 16u * 8u * 4u);
  EXPECT_EQ(words(resources_.current(handle)), std::vector<uint32_t>(16 * 8, 7u));
  resources_.resize({16, 8});
  EXPECT_EQ(resources_.current(handle).handle(), first) << "the same size keeps the buffer";
  resources_.resize({20, 10});
  EXPECT_THROW(resources_.current(handle), Error) << "the new buffer's clear is pending";
  beginFrame();
  gpu::Buffer& resized = resources_.current(handle);
  EXPECT_EQ(resized.size(), 20u * 10u * 4u);
  EXPECT_EQ(words(resized), std::vector<uint32_t>(20 * 10, 7u));
}

// A ping-pong pair: current() is read, previous() written, flip() swaps them.
TEST_F(DeclaredBuffers, APingPongPairFlips) {
  const gpu::BufferHandle handle = resources_.declare({.name = "pair",
                                                       .size = gpu::BufferSize::absolute(64),
                                                       .usage = kCopyable,
                                                       .pairing = gpu::Pairing::PingPong});
  gpu::Buffer& first = resources_.current(handle);
  gpu::Buffer& second = resources_.previous(handle);
  ASSERT_NE(first.handle(), second.handle());
  fill(first, 1u);
  fill(second, 2u);  // a step writes the other one...
  resources_.flip(handle);  // ...and the next reads it
  EXPECT_EQ(resources_.current(handle).handle(), second.handle());
  EXPECT_EQ(resources_.previous(handle).handle(), first.handle());
  EXPECT_EQ(words(resources_.current(handle)), std::vector<uint32_t>(16, 2u));
  resources_.flip(handle);
  EXPECT_EQ(words(resources_.current(handle)), std::vector<uint32_t>(16, 1u));
}

// Through the host, two frames in flight: each frame's slot has its own buffer, the same one every
// time that slot comes round, so the CPU can write (or read back) one while the other is in flight.
class PerFrameScene final : public TestScene {
 public:
  explicit PerFrameScene(const SceneContext& context)
      : perFrame_(context.resources.declare({.name = "per frame",
                                             .size = gpu::BufferSize::absolute(256),
                                             .usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                             .pairing = gpu::Pairing::PerFrame})) {}
  void record(const FrameContext& frame) override {
    seen.push_back({frame.slot, frame.resources.current(perFrame_).handle()});
  }
  std::vector<std::pair<uint32_t, VkBuffer>> seen;  // each frame's slot and buffer

 private:
  gpu::BufferHandle perFrame_;
};

PerFrameScene* perFrameScene = nullptr;

TEST_F(DeclaredBuffers, APerFrameBufferIsADifferentBufferInEachSlot) {
  FramesInFlight run(device(), Assets("/nonexistent"));
  const TestSceneEntry& scene = testScene(perFrameScene);
  run.renderer().setScene(scene.info, scene.create);
  for (int i = 0; i < 6; ++i) run.frame({32, 16});
  const auto& seen = perFrameScene->seen;
  ASSERT_EQ(seen.size(), 6u);
  std::set<VkBuffer> buffers;
  for (size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].first, uint32_t(i % 2)) << "frame " << i;
    EXPECT_EQ(seen[i].second, seen[i % 2].second) << "frame " << i << " has its slot's buffer";
    buffers.insert(seen[i].second);
  }
  EXPECT_EQ(buffers.size(), 2u) << "one buffer per frame in flight";
}

}  // namespace
}  // namespace vitrine::test
