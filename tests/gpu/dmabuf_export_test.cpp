// Frames handed over as DMA-BUFs (gpu/dmabuf_export.h, rig/dmabuf_pool.h): an exported image's memory,
// imported back through its file descriptor, its modifier and its planes' offsets and pitches into a
// second image, holds the pixels written into the first; and a published output whose sink takes
// images copies each frame into one (blitted for B,G,R order) only once it is free, and it is the
// headless frame of its moment. Skipped, saying why, on a device without DMA-BUF export (lavapipe).
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <vector>

#include "gpu/check.h"
#include "gpu/dmabuf_export.h"
#include "gpu/resources.h"
#include "host/offline/offscreen.h"
#include "host/present/readback_output.h"
#include "image/image_io.h"
#include "rig/dmabuf_pool.h"
#include "support/gpu_test.h"

namespace vitrine::test {
namespace {

#define SKIP_WITHOUT_DMABUF()                                                                      \
  do {                                                                                             \
    if (!device().exportsDmaBuf())                                                                 \
      GTEST_SKIP() << device().properties().deviceName                                             \
                   << " does not offer VK_KHR_external_memory_fd, VK_EXT_external_memory_dma_buf " \
                      "and VK_EXT_image_drm_format_modifier together: no DMA-BUF export to test";  \
  } while (0)

// A second image over an exported image's memory, imported from a duplicate of its first plane's fd
// with its modifier and plane layouts given explicitly, as a consumer in another process would.
struct Imported {
  gpu::Unique<VkImage> image;
  gpu::Unique<VkDeviceMemory> memory;
};

Imported import(const gpu::Device& device, const gpu::ExportedImage& exported) {
  std::vector<VkSubresourceLayout> layouts;
  for (const auto& plane : exported.planes())
    layouts.push_back({plane.layout.offset, plane.layout.size, plane.layout.rowPitch, 0, 0});
  VkImageDrmFormatModifierExplicitCreateInfoEXT explicitLayout{
      VK_STRUCTURE_TYPE_IMAGE_DRM_FORMAT_MODIFIER_EXPLICIT_CREATE_INFO_EXT};
  explicitLayout.drmFormatModifier = exported.modifier();
  explicitLayout.drmFormatModifierPlaneCount = uint32_t(layouts.size());
  explicitLayout.pPlaneLayouts = layouts.data();
  VkExternalMemoryImageCreateInfo external{VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_IMAGE_CREATE_INFO, &explicitLayout};
  external.handleTypes = VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT;
  const VkImageCreateInfo info =
      gpu::drmImageInfo(exported.format(), exported.extent(), VK_IMAGE_USAGE_TRANSFER_SRC_BIT, &external);
  VkImage image;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  Imported imported{gpu::Unique<VkImage>(device, image), {}};

  gpu::FileDescriptor fd(dup(exported.planes()[0].fd.get()));
  VkMemoryFdPropertiesKHR fdProperties{VK_STRUCTURE_TYPE_MEMORY_FD_PROPERTIES_KHR};
  VK_CHECK(device.getMemoryFdProperties(device, VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT, fd.get(), &fdProperties));
  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device, image, &requirements);
  requirements.memoryTypeBits &= fdProperties.memoryTypeBits;
  VkMemoryDedicatedAllocateInfo dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO};
  dedicated.image = image;
  VkImportMemoryFdInfoKHR importInfo{VK_STRUCTURE_TYPE_IMPORT_MEMORY_FD_INFO_KHR, &dedicated};
  importInfo.handleType = VK_EXTERNAL_MEMORY_HANDLE_TYPE_DMA_BUF_BIT_EXT;
  importInfo.fd = fd.get();
  imported.memory = device.allocate(requirements, 0, 0, &importInfo);
  (void)fd.release();  // a successful import owns the descriptor
  VK_CHECK(vkBindImageMemory(device, image, imported.memory, 0));
  return imported;
}

// The imported image's texels, row after row: acquired from the external side where the exporter
// released it, then copied into a buffer the CPU reads.
std::vector<uint8_t> readImported(const gpu::Device& device, VkImage image, VkExtent2D extent) {
  gpu::Buffer readback(device, VkDeviceSize(extent.width) * extent.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       gpu::MemoryUse::Readback, "imported readback");
  device.submitNow([&](VkCommandBuffer cmd) {
    gpu::acquireImported(cmd, image, device.queueFamily());
    const VkBufferImageCopy region{0, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {0, 0, 0},
                                   {extent.width, extent.height, 1}};
    vkCmdCopyImageToBuffer(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.handle(), 1, &region);
    gpu::memoryBarrier(cmd, gpu::use::TransferDstBuffer, gpu::use::HostReadBuffer);
  });
  readback.invalidate();
  const auto* bytes = static_cast<const uint8_t*>(readback.mapped());
  return {bytes, bytes + readback.size()};
}

class DmaBufExportTest : public GpuTest {};

TEST_F(DmaBufExportTest, AnExportedImageImportedBackHoldsItsPixels) {
  SKIP_WITHOUT_DMABUF();
  const VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  const auto modifiers = gpu::exportableModifiers(device(), format, usage,
                                                  VK_FORMAT_FEATURE_TRANSFER_SRC_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT);
  ASSERT_FALSE(modifiers.empty()) << "the device exports DMA-BUFs but lists no modifier for 8-bit RGBA copies";
  const VkExtent2D extent{67, 37};  // odd sides: a pitch or tile padding shows as misplaced rows
  std::vector<uint8_t> pattern(size_t(extent.width) * extent.height * 4);
  for (size_t i = 0; i < pattern.size(); ++i) pattern[i] = uint8_t((i * 7 + i / 268) & 0xff);
  for (const auto& entry : modifiers) {
    SCOPED_TRACE(gpu::drm::describeModifier(entry.modifier));
    const std::array<uint64_t, 1> only{entry.modifier};
    gpu::ExportedImage exported(device(), format, extent, usage, only, "exported");
    EXPECT_EQ(exported.modifier(), entry.modifier);
    ASSERT_EQ(exported.planes().size(), entry.planes);
    for (const auto& plane : exported.planes()) {
      EXPECT_GE(fcntl(plane.fd.get(), F_GETFD), 0) << "an open descriptor";
      const off_t size = lseek(plane.fd.get(), 0, SEEK_END);  // a DMA-BUF's size, where the kernel tells it
      if (size >= 0) {
        EXPECT_GE(uint64_t(size), plane.layout.offset + plane.layout.size);
      }
    }
    gpu::Buffer upload(device(), pattern.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUse::Upload, "pattern");
    std::copy(pattern.begin(), pattern.end(), static_cast<uint8_t*>(upload.mapped()));
    device().submitNow([&](VkCommandBuffer cmd) {
      gpu::beginExportedCopy(cmd, exported.handle());
      const VkBufferImageCopy region{0, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {0, 0, 0},
                                     {extent.width, extent.height, 1}};
      vkCmdCopyBufferToImage(cmd, upload.handle(), exported.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
      gpu::endExportedCopy(cmd, exported.handle(), device().queueFamily());
    });
    const Imported imported = import(device(), exported);
    const std::vector<uint8_t> got = readImported(device(), imported.image, extent);
    size_t wrong = 0;
    for (size_t i = 0; i < pattern.size(); ++i) wrong += got[i] != pattern[i];
    EXPECT_EQ(wrong, 0u) << "bytes differing after the round trip through the DMA-BUF";
  }
}

// Plays PipeWire's part: makes the exported images a stream would ask for, gives them to the output's
// hand-over as the consumer would give buffers back, and takes the finished frames.
class ImageSink final : public host::FrameSink {
 public:
  ImageSink() : pool(std::make_shared<rig::DmaBufPool>(nullptr)) {}
  void frame(const host::PublishedFrame&) override { ++readBack; }
  std::shared_ptr<host::ImageHandOver> images() override { return pool; }
  host::Output::Health health() const override { return {.kind = "test"}; }
  std::shared_ptr<rig::DmaBufPool> pool;
  int readBack = 0;
};

TEST_F(DmaBufExportTest, APublishedOutputCopiesEachFrameIntoAFreeExportedImage) {
  SKIP_WITHOUT_DMABUF();
  const VkExtent2D size{96, 54};
  const VkFormat frame = host::ReadbackOutput::frameFormat(device());
  const bool srgb = frame == VK_FORMAT_R8G8B8A8_SRGB;
  for (const bool blueFirst : {false, true}) {
    SCOPED_TRACE(blueFirst ? "B,G,R order (blitted)" : "R,G,B order (copied)");
    const VkFormat format = blueFirst ? (srgb ? VK_FORMAT_B8G8R8A8_SRGB : VK_FORMAT_B8G8R8A8_UNORM) : frame;
    const auto modifiers = gpu::exportableModifiers(
        device(), format, VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
        VK_FORMAT_FEATURE_TRANSFER_DST_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT |
            (blueFirst ? VK_FORMAT_FEATURE_BLIT_DST_BIT : 0));
    if (modifiers.empty()) continue;
    host::OffscreenConfig config;
    config.scene = "kifs";
    config.size = size;
    config.startTime = 2.0;
    host::Offscreen offscreen(device(), config);
    auto sink = std::make_unique<ImageSink>();
    ImageSink& images = *sink;
    std::vector<uint64_t> list;
    for (const auto& entry : modifiers) list.push_back(entry.modifier);
    std::array<int, 2> keys{};  // two buffers, as a stream of two
    std::map<const void*, const gpu::ExportedImage*> exported;
    for (const int& key : keys) {
      auto image = std::make_unique<gpu::ExportedImage>(device(), format, size,
                                                        VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                                        list, "stream buffer");
      exported[&key] = image.get();
      images.pool->add(&key, std::move(image), size, format);
    }
    images.pool->setActive(true);
    host::ReadbackOutput output(device(), "published", {}, size, std::move(sink));
    offscreen.addOutput(output);

    // The stream still holds both buffers: the frame is not drawn for the output, only counted.
    offscreen.renderFrame();
    EXPECT_EQ(output.dropped(), 1u);
    images.pool->given(&keys[0]);
    const uint64_t index = offscreen.frames();
    offscreen.renderFrame();
    const std::vector<uint8_t> want = srgb8(offscreen.readback());
    offscreen.renderFrame();  // the next frame's acquire sees the copy finished, if the GPU has
    device().waitIdle();
    images.pool->markFinished(device().completed());
    uint64_t superseded = 0;
    const auto done = images.pool->takeDone(superseded);
    ASSERT_TRUE(done) << "the copy into the free image finished";
    EXPECT_EQ(done->key, &keys[0]);
    EXPECT_EQ(done->index, index);
    EXPECT_EQ(images.readBack, 0) << "no frame was read back to the CPU";

    const Imported imported = import(device(), *exported[done->key]);
    const std::vector<uint8_t> got = readImported(device(), imported.image, size);
    ASSERT_EQ(got.size(), want.size());
    int worst = 0;
    for (size_t i = 0; i < got.size(); i += 4)
      for (size_t c = 0; c < 3; ++c) {
        const size_t from = blueFirst ? i + 2 - c : i + c;  // B,G,R holds red third
        worst = std::max(worst, std::abs(int(got[from]) - int(want[i + c])));
      }
    EXPECT_LE(worst, 1) << "the frame handed over is the headless frame of its moment";
  }
}

}  // namespace
}  // namespace vitrine::test
