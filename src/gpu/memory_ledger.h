#pragma once
// Every VkDeviceMemory this process holds, counted where it is allocated (Device::allocate) and freed
// (Unique<VkDeviceMemory>): the soak's proof that Vulkan allocations stay flat, on any driver, where
// resident memory only shows them on a CPU device like lavapipe.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace vitrine::gpu {

struct MemoryTally {
  uint64_t allocations = 0;
  uint64_t bytes = 0;
};

void noteAllocated(VkDeviceMemory memory, VkDeviceSize bytes);
void noteFreed(VkDeviceMemory memory);
MemoryTally liveDeviceMemory();  // across every device of the process

}  // namespace vitrine::gpu
