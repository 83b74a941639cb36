#include "host/present/readback_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "gpu/device.h"
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
    : Output(std::move(name), warp), device_(device), sink_(std::move(sink)) {
  build(extent);
}

// The image and buffers may still be in the frames in flight: retired behind them, not waited for.
ReadbackOutput::~ReadbackOutput() {
  if (image_) device_.retire(std::move(image_));
  if (copies_) device_.retire(std::move(copies_));
}

void ReadbackOutput::build(VkExtent2D extent) {
  gpu::checkImageSize(device_, extent);
  if (image_) device_.retire(std::move(image_));
  if (copies_) device_.retire(std::move(copies_));
  // As a swapchain's images: written by the compute present, which encodes sRGB into UNORM texels,
  // where the device stores without a declared format; else blitted into sRGB texels, which the blit
  // encodes. Either way the bytes read back are the display's.
  const bool compute = device_.storageWriteWithoutFormat();
  gpu::ImageDesc desc;
  desc.extent = {extent.width, extent.height, 1};
  desc.format = compute ? VK_FORMAT_R8G8B8A8_UNORM : VK_FORMAT_R8G8B8A8_SRGB;
  desc.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | (compute ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  image_ = gpu::Image(device_, desc, fmt::format("{} frame", name()));
  copies_ = std::make_unique<Copies>(device_, extent, fmt::format("{} readback", name()));
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
  if (const auto wanted = sink_->wantedExtent(); wanted && wanted->width > 0 && wanted->height > 0) {
    const uint32_t limit = device_.limits().maxImageDimension2D;
    const VkExtent2D size{std::min(wanted->width, limit), std::min(wanted->height, limit)};
    if (size.width != extent().width || size.height != extent().height) build(size);
  }
  if (!sink_->taking()) return false;
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
  const uint64_t tag = copied_;
  if (!copies_->ring.record(cmd, image_, double(tag))) return;  // acquire() found a buffer free
  stamps_[tag % stamps_.size()] = {shown.frame, shown.time};
  ++copied_;
}

void ReadbackOutput::present() { copies_->ring.submitted(device_.lastSubmitted()); }

Output::Health ReadbackOutput::health() const {
  Health health = sink_->health();
  health.dropped += dropped_;
  return health;
}

}  // namespace vitrine::host
