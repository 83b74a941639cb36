#include "host/gallery/frame_slot.h"

#include <fmt/format.h>

#include "gpu/check.h"
#include "gpu/sync_objects.h"

#include <vector>

namespace vitrine::host {

FrameSlot::FrameSlot(const gpu::Device& device, uint32_t index)
    : device_(&device),
      pool_(gpu::createCommandPool(device, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT, fmt::format("frame {} pool", index))),
      imageAcquired_(gpu::createSemaphore(device, fmt::format("frame {} image acquired", index))) {
  const VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool_,
                                          VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
  VK_CHECK(vkAllocateCommandBuffers(device, &alloc, &cmd_));
  device.name(cmd_, VK_OBJECT_TYPE_COMMAND_BUFFER, fmt::format("frame {}", index));
}

void FrameSlot::wait() const {
  if (serial_) device_->wait(serial_);
}

VkCommandBuffer FrameSlot::begin() {
  VK_CHECK(vkResetCommandPool(*device_, pool_, 0));
  const VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                      VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  VK_CHECK(vkBeginCommandBuffer(cmd_, &info));
  return cmd_;
}

void FrameSlot::submit(VkPipelineStageFlags2 acquireStage, VkSemaphore renderFinished,
                       std::span<const std::pair<VkSemaphore, VkSemaphore>> more) {
  VK_CHECK(vkEndCommandBuffer(cmd_));
  std::vector<VkSemaphoreSubmitInfo> waits, signals;
  const auto add = [&](VkSemaphore acquired, VkSemaphore finished) {
    waits.push_back({VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, nullptr, acquired, 0, acquireStage, 0});
    signals.push_back({VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, nullptr, finished, 0, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0});
  };
  add(imageAcquired_, renderFinished);
  for (const auto& [acquired, finished] : more) add(acquired, finished);
  serial_ = device_->submit({cmd_, waits, signals});
}

}  // namespace vitrine::host
