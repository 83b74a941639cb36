#pragma once
// Buffer work that compute-only scenes need besides dispatches: clearing a buffer to a value and
// dispatching with a workgroup count that an earlier pass wrote, with the uses (gpu/barriers.h)
// that order them. The buffer's tracked use derives every barrier, as elsewhere.
#include "gpu/resources.h"

namespace vitrine::gpu {

namespace use {
// Atomics: a compute pass that reads and writes the same buffer (a visibility buffer's atomicMin).
inline constexpr BufferUse ComputeReadWriteBuffer{
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// The arguments of vkCmdDispatchIndirect, which the dispatched shader may read too (its count).
inline constexpr BufferUse DispatchIndirectBuffer{
    VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
}  // namespace use

// Every 32-bit word of the buffer set to `value` (vkCmdFillBuffer: the copy engine's clear, no
// shader), then the buffer made ready for `after`. Needs VK_BUFFER_USAGE_TRANSFER_DST_BIT.
void fillBuffer(VkCommandBuffer cmd, Buffer& buffer, uint32_t value, const BufferUse& after);

// Dispatches the bound compute program with the VkDispatchIndirectCommand at `offset` in `args`
// (VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT), after what last wrote it.
void dispatchIndirect(VkCommandBuffer cmd, Buffer& args, VkDeviceSize offset = 0);

}  // namespace vitrine::gpu
