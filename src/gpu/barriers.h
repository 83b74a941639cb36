#pragma once
// Synchronization2 barriers derived from what a resource did last and what it does next. Host and
// scenes name uses (use::ComputeWrite, use::FragmentSample, ...); images and buffers
// (gpu/resources.h) remember their last use, so nobody writes a barrier by hand.
#include <vulkan/vulkan.h>

namespace vitrine::gpu {

struct ImageUse {
  VkPipelineStageFlags2 stage;
  VkAccessFlags2 access;
  VkImageLayout layout;
};

struct BufferUse {
  VkPipelineStageFlags2 stage;
  VkAccessFlags2 access;
};

namespace use {
constexpr VkPipelineStageFlags2 kShaders =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
// Images.
inline constexpr ImageUse Discard{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
inline constexpr ImageUse ComputeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                       VK_IMAGE_LAYOUT_GENERAL};
inline constexpr ImageUse ComputeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                                      VK_IMAGE_LAYOUT_GENERAL};
inline constexpr ImageUse ComputeReadWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                           VK_IMAGE_LAYOUT_GENERAL};
// An image whose mips compute passes read and write in turn (a mip-chain bloom: sample level L - 1,
// store level L): both accesses, in GENERAL, so each step's barrier covers the next step's reads.
inline constexpr ImageUse ComputeSampleWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                             VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                             VK_IMAGE_LAYOUT_GENERAL};
inline constexpr ImageUse ComputeSample{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
inline constexpr ImageUse FragmentSample{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
// Last frame's image of a history pair, sampled by a compute or fragment shader (TAA, accumulation).
inline constexpr ImageUse HistoryRead{kShaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
inline constexpr ImageUse ColorAttachment{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                          VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT |
                                              VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                          VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
inline constexpr ImageUse DepthAttachment{VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                              VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                          VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                                          VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL};
// A depth buffer sampled after its pass (soft particles, depth of field).
inline constexpr ImageUse DepthRead{kShaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                                    VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL};
inline constexpr ImageUse TransferSrc{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
inline constexpr ImageUse TransferDst{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
inline constexpr ImageUse Present{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};

// Buffers.
inline constexpr BufferUse BufferNone{VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};
inline constexpr BufferUse ComputeWriteBuffer{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
inline constexpr BufferUse ComputeReadBuffer{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                             VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
inline constexpr BufferUse VertexReadBuffer{VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
inline constexpr BufferUse FragmentReadBuffer{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                              VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
// Atomics: a compute pass that reads and writes the same buffer (a visibility buffer's atomicMin).
inline constexpr BufferUse ComputeReadWriteBuffer{
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
// The arguments of vkCmdDispatchIndirect, which the dispatched shader may read too (its count).
inline constexpr BufferUse DispatchIndirectBuffer{
    VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
    VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT};
inline constexpr BufferUse IndirectBuffer{VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                                          VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT};
inline constexpr BufferUse TransferDstBuffer{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
inline constexpr BufferUse TransferSrcBuffer{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
inline constexpr BufferUse HostReadBuffer{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
}  // namespace use

// True when `access` only reads: two reads in a row need no barrier between them.
bool readOnly(VkAccessFlags2 access);

// The barrier from `before` to `after` on mip levels [baseMip, baseMip + mips) of an image.
void transition(VkCommandBuffer cmd, VkImage image, const ImageUse& before, const ImageUse& after,
                VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT, uint32_t baseMip = 0,
                uint32_t mips = VK_REMAINING_MIP_LEVELS);

// A global memory dependency, for buffers written by one pass and read by the next.
void memoryBarrier(VkCommandBuffer cmd, const BufferUse& before, const BufferUse& after);

}  // namespace vitrine::gpu
