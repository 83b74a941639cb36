#pragma once
// A gallery's frame loop without the window, for GPU tests: two frames in flight (a frame is recorded
// while the previous one may still run), any output size each frame, the scene updated once a frame.
#include "gpu/sync_objects.h"
#include "host/scene_renderer.h"
#include "image/image.h"

#include <array>

namespace vitrine::test {

class FramesInFlight {
 public:
  FramesInFlight(const gpu::Device& device, Assets assets)
      : device_(device), assets_(std::move(assets)), programs_(device), guard_(device, programs_),
        renderer_(device, programs_, assets_, 2),
        pool_(gpu::createCommandPool(device, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, "test frames")) {
    const VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool_,
                                            VK_COMMAND_BUFFER_LEVEL_PRIMARY, 2};
    vkAllocateCommandBuffers(device, &alloc, cmds_.data());
  }
  ~FramesInFlight() { device_.waitIdle(); }
  FramesInFlight(const FramesInFlight&) = delete;
  FramesInFlight& operator=(const FramesInFlight&) = delete;

  host::SceneRenderer& renderer() { return renderer_; }
  // Frames from now on go through the flash guard (or not), as the gallery's switch does.
  void guard(bool on) { renderer_.setFlashGuard(on ? &guard_ : nullptr); }

  void frames(int count, VkExtent2D size) {
    for (int i = 0; i < count; ++i) frame(size);
  }

  void frame(VkExtent2D size) {
    const uint32_t slot = uint32_t(input_.frame % 2);
    if (serials_[slot]) device_.wait(serials_[slot]);
    gpu::Image& output = outputs_[slot];
    if (!output || output.extent2d().width != size.width || output.extent2d().height != size.height) {
      if (output) device_.retire(std::move(output));
      gpu::ImageDesc desc;
      desc.extent = {size.width, size.height, 1};
      desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
      output = gpu::Image(device_, desc, "test output");
    }
    VkCommandBuffer cmd = cmds_[slot];
    vkResetCommandBuffer(cmd, 0);
    const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                         VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(cmd, &begin);
    renderer_.scene().update(input_);
    output.discard();
    renderer_.record(cmd, slot, input_,
                     host::BlitDestination{output.handle(), size, output.lastUse(), gpu::use::TransferSrc, output.view()});
    output.assumeUse(gpu::use::TransferSrc);
    vkEndCommandBuffer(cmd);
    serials_[slot] = device_.submit({cmd, {}, {}});
    last_ = slot;
    input_.time += input_.dt;
    ++input_.frame;
  }

  // The first texel's red channel of the last frame's output; waits for the device.
  float firstTexel() {
    device_.waitIdle();
    gpu::Image& output = outputs_[last_];
    gpu::Buffer staging(device_, VkDeviceSize(output.extent2d().width) * output.extent2d().height * 8,
                        VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::Readback, "test readback");
    device_.submitNow([&](VkCommandBuffer cmd) { gpu::recordReadback(cmd, output, staging); });
    staging.invalidate();
    return imageFromHalves(output.extent2d().width, output.extent2d().height, staging.view<const uint16_t>()).pixels[0];
  }

 private:
  const gpu::Device& device_;
  Assets assets_;
  gpu::ProgramLibrary programs_;
  host::FlashGuard guard_;  // before the renderer, which drains the device before it goes
  host::SceneRenderer renderer_;
  gpu::Unique<VkCommandPool> pool_;
  std::array<VkCommandBuffer, 2> cmds_{};
  std::array<uint64_t, 2> serials_{};
  std::array<gpu::Image, 2> outputs_;
  uint32_t last_ = 0;
  FrameInput input_;
};

}  // namespace vitrine::test
