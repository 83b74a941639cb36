#include "host/present/readback_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "core/error.h"
#include "gpu/device.h"
#include "gpu/dmabuf_export.h"
#include "gpu/frame_resources.h"

namespace vitrine::host {

struct ReadbackOutput::Copies {
  Copies(const gpu::Device& device, VkExtent2D size, const std::string& name)
      : resources(device), ring(device, resources, VkDeviceSize(size.width) * size.height * 4, kBuffers, name), extent(size) {}
  gpu::FrameResources resources;
  gpu::ReadbackRing ring;  // refers to `resources`: declared after it
  VkExtent2D extent;
};

ReadbackOutput::ReadbackOutput(const gpu::Device& device, std::string name, const maths::OutputWarp& warp,
                               VkExtent2D extent, std::unique_ptr<FrameSink> sink)
    : Output(std::move(name), warp), device_(device), sink_(std::move(sink)), images_(sink_->images()) {
  build(extent);
}

// The image and buffers may still be in the frames in flight: retired behind them, not waited for. The
// sink goes first: the images it handed over come back to the hand-over, retired with it.
ReadbackOutput::~ReadbackOutput() {
  sink_.reset();
  if (images_) device_.retire(std::move(images_));
  if (image_) device_.retire(std::move(image_));
  if (copies_) device_.retire(std::move(copies_));
}

VkFormat ReadbackOutput::frameFormat(const gpu::Device& device) {
  return device.storageWriteWithoutFormat() ? VK_FORMAT_R8G8B8A8_UNORM : VK_FORMAT_R8G8B8A8_SRGB;
}

void ReadbackOutput::build(VkExtent2D extent) {
  gpu::checkImageSize(device_, extent);
  // As a swapchain's images: written by the compute present, which encodes sRGB into UNORM texels,
  // where the device stores without a declared format; else blitted into sRGB texels, which the blit
  // encodes. Either way the bytes read back are the display's.
  const bool compute = device_.storageWriteWithoutFormat();
  gpu::ImageDesc desc;
  desc.extent = {extent.width, extent.height, 1};
  desc.format = frameFormat(device_);
  desc.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | (compute ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  // Both made before the old ones go, so a size that fails leaves the output as it was.
  gpu::Image image(device_, desc, fmt::format("{} frame", name()));
  auto copies = std::make_unique<Copies>(device_, extent, fmt::format("{} readback", name()));
  if (image_) device_.retire(std::move(image_));
  if (copies_) device_.retire(std::move(copies_));
  image_ = std::move(image);
  copies_ = std::move(copies);
}

void ReadbackOutput::collect() {
  const auto copy = copies_->ring.poll();
  if (!copy) return;
  dropped_ += copy->superseded;
  const Stamp& stamp = stamps_[uint64_t(copy->tag) % stamps_.size()];
  const VkExtent2D size = copies_->extent;
  sink_->frame(PublishedFrame{copy->bytes, size.width, size.height, size.width * 4, stamp.index, stamp.time});
}

bool ReadbackOutput::acquire(uint32_t, bool) {
  collect();
  if (images_) images_->finished(device_.completed(), device_);
  target_.reset();
  targetCopied_ = false;
  if (const auto wanted = sink_->wantedExtent(); wanted && wanted->width > 0 && wanted->height > 0) {
    const uint32_t limit = device_.limits().maxImageDimension2D;
    const VkExtent2D size{std::min(wanted->width, limit), std::min(wanted->height, limit)};
    const bool refused = refused_ && refused_->width == size.width && refused_->height == size.height;
    if ((size.width != extent().width || size.height != extent().height) && !refused) {
      // A size the device cannot hold (memory, a limit) keeps the output's; said once, not asked again.
      try {
        build(size);
      } catch (const Error& e) {
        refused_ = size;
        std::fprintf(stderr, "vitrine: %s: cannot publish at %ux%u (%s); staying at %ux%u\n", name().c_str(),
                     size.width, size.height, e.what(), extent().width, extent().height);
      }
    }
  }
  if (!sink_->taking()) return false;
  if (images_ && images_->active()) {
    target_ = images_->take(extent());
    if (target_) return true;
    ++dropped_;  // the consumer holds every image, or none is of this size yet: not drawn for this output
    return false;
  }
  if (!copies_->ring.full()) return true;
  ++dropped_;  // every buffer still on its way back: this frame is not drawn for this output
  return false;
}

BlitDestination ReadbackOutput::destination(VkPipelineStageFlags2) const {
  gpu::ImageUse before = image_.lastUse();
  before.layout = VK_IMAGE_LAYOUT_UNDEFINED;  // every texel is written: last frame's need not be kept
  const bool compute = device_.storageWriteWithoutFormat();
  return {image_.handle(), image_.extent2d(), before, gpu::use::TransferSrc,
          compute ? image_.view() : VK_NULL_HANDLE, compute, &warp(), "publish"};
}

void ReadbackOutput::drawn(VkCommandBuffer cmd, gpu::PassTimer* timer, const FrameInput& shown) {
  image_.assumeUse(gpu::use::TransferSrc);  // where the present pass left it
  gpu::Pass pass(device_, timer, cmd, "publish copy");
  if (target_) {
    copyToTarget(cmd);
    targetStamp_ = {shown.frame, shown.time};
    targetCopied_ = true;
    return;
  }
  const uint64_t tag = copied_;
  if (!copies_->ring.record(cmd, image_, double(tag))) return;  // acquire() found a buffer free
  stamps_[tag % stamps_.size()] = {shown.frame, shown.time};
  ++copied_;
}

// The frame's image into the hand-over's: copied where the byte orders agree, else blitted (a blit of
// equal sizes swaps the channels and, between two sRGB formats, decodes and re-encodes each exactly).
void ReadbackOutput::copyToTarget(VkCommandBuffer cmd) {
  const VkExtent2D size = extent();
  gpu::beginExportedCopy(cmd, target_->image);
  const VkImageSubresourceLayers layers{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  if (target_->format == image_.format()) {
    const VkImageCopy region{layers, {0, 0, 0}, layers, {0, 0, 0}, {size.width, size.height, 1}};
    vkCmdCopyImage(cmd, image_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target_->image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  } else {
    const VkOffset3D corner{int32_t(size.width), int32_t(size.height), 1};
    const VkImageBlit region{layers, {{0, 0, 0}, corner}, layers, {{0, 0, 0}, corner}};
    vkCmdBlitImage(cmd, image_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target_->image,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_NEAREST);
  }
  gpu::endExportedCopy(cmd, target_->image, device_.queueFamily());
}

void ReadbackOutput::present() {
  if (target_) {
    if (targetCopied_) images_->submitted(target_->id, device_.lastSubmitted(), targetStamp_.index, targetStamp_.time);
    target_.reset();  // one taken but not copied into is free again at the next take()
    targetCopied_ = false;
    return;
  }
  copies_->ring.submitted(device_.lastSubmitted());
}

Output::Health ReadbackOutput::health() const {
  Health health = sink_->health();
  health.dropped += dropped_;
  return health;
}

}  // namespace vitrine::host
