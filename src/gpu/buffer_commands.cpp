#include "gpu/buffer_commands.h"

namespace vitrine::gpu {

void fillBuffer(VkCommandBuffer cmd, Buffer& buffer, uint32_t value, const BufferUse& after) {
  buffer.use(cmd, use::TransferDstBuffer);
  vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, value);
  buffer.use(cmd, after);
}

void dispatchIndirect(VkCommandBuffer cmd, Buffer& args, VkDeviceSize offset) {
  args.use(cmd, use::DispatchIndirectBuffer);
  vkCmdDispatchIndirect(cmd, args.handle(), offset);
}

}  // namespace vitrine::gpu
