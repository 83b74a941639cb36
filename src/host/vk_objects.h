#pragma once
// The host's small command and synchronisation objects, each created owned and named, so a debugger
// capture of the gallery reads as what each object is for.
#include "gpu/device.h"

#include <string>

namespace vitrine::host {

gpu::Unique<VkSemaphore> createSemaphore(const gpu::Device& device, const std::string& name);
gpu::Unique<VkFence> createFence(const gpu::Device& device, bool signalled, const std::string& name);
gpu::Unique<VkCommandPool> createCommandPool(const gpu::Device& device, VkCommandPoolCreateFlags flags,
                                             const std::string& name);

}  // namespace vitrine::host
