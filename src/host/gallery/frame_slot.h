#pragma once
// What one frame in flight owns, so the CPU can record a frame while the GPU still runs the previous
// one: a command pool and buffer, the serial of its last submission (the device's timeline says when
// the GPU is done with them), and the semaphore its swapchain image is acquired with.
#include "gpu/device.h"

#include <span>
#include <utility>

namespace vitrine::host {

class FrameSlot {
 public:
  FrameSlot(const gpu::Device& device, uint32_t index);

  void wait() const;  // until the GPU has finished this slot's last frame
  VkSemaphore imageAcquired() const { return imageAcquired_; }
  VkCommandBuffer begin();  // recycles the slot's commands: only after wait()
  // Runs the recorded frame once the image is acquired; signals renderFinished for presentation. `more`:
  // the other outputs' images drawn in the same frame, each (acquired, render finished).
  void submit(VkPipelineStageFlags2 acquireStage, VkSemaphore renderFinished,
              std::span<const std::pair<VkSemaphore, VkSemaphore>> more = {});

 private:
  const gpu::Device* device_;
  gpu::Unique<VkCommandPool> pool_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;  // freed with the pool
  uint64_t serial_ = 0;                   // 0: nothing submitted yet
  gpu::Unique<VkSemaphore> imageAcquired_;
};

}  // namespace vitrine::host
