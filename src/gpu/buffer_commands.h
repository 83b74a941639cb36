#pragma once
// Buffer work that compute-only scenes need besides dispatches: clearing a buffer to a value and
// dispatching with a workgroup count that an earlier pass wrote. Their uses are named with all the
// others in gpu/barriers.h. The buffer's tracked use derives every barrier, as elsewhere.
#include "gpu/resources.h"

namespace vitrine::gpu {

// Every 32-bit word of the buffer set to `value` (vkCmdFillBuffer: the copy engine's clear, no
// shader), then the buffer made ready for `after`. Needs VK_BUFFER_USAGE_TRANSFER_DST_BIT.
void fillBuffer(VkCommandBuffer cmd, Buffer& buffer, uint32_t value, const BufferUse& after);

// Dispatches the bound compute program with the VkDispatchIndirectCommand at `offset` in `args`
// (VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT), after what last wrote it.
void dispatchIndirect(VkCommandBuffer cmd, Buffer& args, VkDeviceSize offset = 0);

}  // namespace vitrine::gpu
