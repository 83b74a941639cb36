#include "gpu/sync_objects.h"

#include "gpu/check.h"

namespace vitrine::gpu {

Unique<VkSemaphore> createSemaphore(const Device& device, const std::string& name) {
  const VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore;
  VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
  device.name(semaphore, VK_OBJECT_TYPE_SEMAPHORE, name);
  return Unique<VkSemaphore>(device, semaphore);
}

Unique<VkSemaphore> createTimelineSemaphore(const Device& device, const std::string& name) {
  const VkSemaphoreTypeCreateInfo type{VK_STRUCTURE_TYPE_SEMAPHORE_TYPE_CREATE_INFO, nullptr,
                                       VK_SEMAPHORE_TYPE_TIMELINE, 0};
  const VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO, &type};
  VkSemaphore semaphore;
  VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
  device.name(semaphore, VK_OBJECT_TYPE_SEMAPHORE, name);
  return Unique<VkSemaphore>(device, semaphore);
}

Unique<VkFence> createFence(const Device& device, bool signalled, const std::string& name) {
  VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (signalled) info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VkFence fence;
  VK_CHECK(vkCreateFence(device, &info, nullptr, &fence));
  device.name(fence, VK_OBJECT_TYPE_FENCE, name);
  return Unique<VkFence>(device, fence);
}

Unique<VkCommandPool> createCommandPool(const Device& device, VkCommandPoolCreateFlags flags, const std::string& name) {
  VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  info.flags = flags;
  info.queueFamilyIndex = device.queueFamily();
  VkCommandPool pool;
  VK_CHECK(vkCreateCommandPool(device, &info, nullptr, &pool));
  device.name(pool, VK_OBJECT_TYPE_COMMAND_POOL, name);
  return Unique<VkCommandPool>(device, pool);
}

}  // namespace vitrine::gpu
