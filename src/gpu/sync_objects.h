#pragma once
// Small command and synchronisation objects, each created owned and named, so a debugger capture or
// a validation message says what each object is for.
#include <string>

#include "gpu/device.h"

namespace vitrine::gpu {

Unique<VkSemaphore> createSemaphore(const Device& device, const std::string& name);
Unique<VkSemaphore> createTimelineSemaphore(const Device& device, const std::string& name);  // starts at 0
Unique<VkFence> createFence(const Device& device, bool signalled, const std::string& name);
Unique<VkCommandPool> createCommandPool(const Device& device, VkCommandPoolCreateFlags flags, const std::string& name);

}  // namespace vitrine::gpu
