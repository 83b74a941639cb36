#include "host/flash_guard.h"

#include "host/flash_guard_math.h"
#include "shaders/host/flash_guard_blocks.h"

#include <cmath>

namespace vitrine::host {

FlashGuard::FlashGuard(const gpu::Device& device, gpu::ProgramLibrary& programs)
    : device_(device),
      measure_(programs, "host/flash_measure.comp"),
      decide_(programs, "host/flash_decide.comp"),
      show_(programs, "host/flash_present.comp"),
      state_(device, sizeof(shader::HostFlashGuardState), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, gpu::MemoryUse::Device,
             "flash guard state") {}

gpu::Image& FlashGuard::guard(VkCommandBuffer cmd, const GuardSources& sources, VkExtent2D extent, double time) {
  bool fresh = !(time >= lastTime_);  // the first frame, or time went back: no history to count against
  if (!held_ || held_.extent2d().width != extent.width || held_.extent2d().height != extent.height) {
    if (held_) device_.retire(std::move(held_));  // the frame in flight may still read it
    gpu::ImageDesc desc;
    desc.extent = {extent.width, extent.height, 1};
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;  // measured, then presented
    held_ = gpu::Image(device_, desc, "flash guard held frame");
    fresh = true;
  }
  const float dt = fresh ? 0.0f : float(time - lastTime_);
  lastTime_ = time;
  const VkSampler linear = device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp);
  const VkImageLayout sampled = gpu::use::ComputeSample.layout;
  // The measure and the present read the same: the frame (and the one fading in), the held frame, the state.
  const gpu::Bindings frame = gpu::Bindings()
                                  .sampledImage("source", sources.source, linear, sampled)
                                  .sampledImage("incoming", sources.incoming, linear, sampled)
                                  .storageImage("held", held_.view())
                                  .storageBuffer("FlashGuard", state_.handle());

  if (!fresh) {
    held_.use(cmd, gpu::use::ComputeRead);
    state_.use(cmd, gpu::use::ComputeReadWriteBuffer);
    measure_.bind(cmd);
    measure_.push(cmd, frame);
    measure_.constants(cmd, shader::HostFlashMeasurePush{sources.fade});
    measure_.dispatchOver(cmd, extent);
  }

  state_.use(cmd, gpu::use::ComputeReadWriteBuffer);
  decide_.bind(cmd);
  decide_.push(cmd, gpu::Bindings().storageBuffer("FlashGuard", state_.handle()));
  decide_.constants(cmd, shader::HostFlashDecidePush{dt, flash::flashArea(extent.width, extent.height),
                                                     fresh ? 1u : 0u});
  decide_.dispatchOver(cmd, 1u);

  if (fresh) held_.discard();
  held_.use(cmd, gpu::use::ComputeReadWrite);
  state_.use(cmd, gpu::use::ComputeReadBuffer);
  show_.bind(cmd);
  show_.push(cmd, frame);
  show_.constants(cmd, shader::HostFlashPresentPush{sources.fade, fresh ? 0u : 1u});
  show_.dispatchOver(cmd, extent);
  return held_;
}

}  // namespace vitrine::host
