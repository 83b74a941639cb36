#include "scenes/noodles/raster_pass.h"

#include "core/error.h"
#include "gpu/buffer_commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <span>

namespace vitrine::noodles {
namespace {

constexpr VkDeviceSize kKeyBytes = 8;        // one uint64_t key a sample
constexpr VkDeviceSize kBigEntryBytes = 4;  // a chunk-local segment index

const gpu::ProgramLayout kRasterLayout{{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                        VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
                                       sizeof(RasterPush)};

// The keys are 64-bit atomicMin targets: shaderInt64 and shaderBufferInt64Atomics (Vulkan 1.2 core,
// optional; lavapipe and NVIDIA have both), enabled by the device when present. Checked before the
// raster programs are built, which without them would be invalid pipelines, not a clear message.
gpu::ProgramLibrary& programsWithInt64Atomics(const SceneContext& context) {
  VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f12};
  vkGetPhysicalDeviceFeatures2(context.device.physical(), &features);
  if (!features.features.shaderInt64 || !f12.shaderBufferInt64Atomics)
    throw Error(fmt::format("noodles: {} has no 64-bit storage-buffer atomics (shaderInt64, "
                            "shaderBufferInt64Atomics), which its tube rasteriser needs",
                            context.device.properties().deviceName));
  return context.programs;
}

}  // namespace

RasterPass::RasterPass(const SceneContext& context)
    : device_(context.device),
      segments_(programsWithInt64Atomics(context), "noodles/raster.comp", kRasterLayout),
      bigSegments_(context.programs, "noodles/raster_big.comp", kRasterLayout),
      bigList_(context.device, kBigCapacity * kBigEntryBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                gpu::MemoryUse::Device, "noodles big segments"),
      counters_(
          context.device, 4 * sizeof(uint32_t),
          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
          gpu::MemoryUse::Device, "noodles big-segment counters") {}

void RasterPass::ensureVisibility(VkExtent2D extent, bool multisample) {
  const VkDeviceSize pixels = VkDeviceSize(extent.width) * extent.height;
  // Four samples need four keys a pixel; where that is more than one binding may cover (4K on
  // lavapipe's 128 MiB), the picture falls back to one sample rather than failing.
  const bool fits = pixels * 4 * kKeyBytes <= device_.limits().maxStorageBufferRange;
  const uint32_t samplesPerAxis = multisample && fits ? 2 : 1;
  if (visibility_ && extent.width == extent_.width && extent.height == extent_.height &&
      samplesPerAxis == samplesPerAxis_)
    return;
  if (visibility_) device_.retire(std::move(visibility_));  // frames in flight may still read it
  visibility_ = gpu::Buffer(device_, pixels * samplesPerAxis * samplesPerAxis * kKeyBytes,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            gpu::MemoryUse::Device, "noodles visibility");
  extent_ = extent;
  samplesPerAxis_ = samplesPerAxis;
}

void RasterPass::record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, const TubeView& view) {
  ensureVisibility(frame.target.extent2d(), view.multisample);
  gpu::fillBuffer(frame.cmd, visibility_, 0xffffffffu, gpu::use::ComputeReadWriteBuffer);  // all keys empty

  RasterPush push = rasterPush(view, layout, samplesPerAxis_);
  push.bigCapacity = kBigCapacity;
  for (const StrandChunk& chunk : layout.chunks) {
    // Nothing listed yet; the big-segment pass's y and z group counts are 1.
    constexpr std::array<uint32_t, 4> kReset{0, 1, 1, 0};
    frame.upload(counters_, 0, std::as_bytes(std::span(kReset)), gpu::use::ComputeReadWriteBuffer);
    bigList_.use(frame.cmd, gpu::use::ComputeWriteBuffer);
    visibility_.use(frame.cmd, gpu::use::ComputeReadWriteBuffer);
    const gpu::Bindings bindings = gpu::Bindings()
                                       .storageBuffer(nodes, chunk.offset, chunk.bytes)
                                       .storageBuffer(visibility_.handle())
                                       .storageBuffer(bigList_.handle())
                                       .storageBuffer(counters_.handle());
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    push.invocationsPerRow = chunk.rasterGroups.x * kRasterGroupSize;
    segments_.bind(frame.cmd);
    segments_.push(frame.cmd, bindings);
    segments_.constants(frame.cmd, push);
    vkCmdDispatch(frame.cmd, chunk.rasterGroups.x, chunk.rasterGroups.y, 1);  // one invocation a segment

    bigList_.use(frame.cmd, gpu::use::ComputeReadBuffer);
    visibility_.use(frame.cmd, gpu::use::ComputeReadWriteBuffer);
    bigSegments_.bind(frame.cmd);
    bigSegments_.push(frame.cmd, bindings);
    bigSegments_.constants(frame.cmd, push);
    gpu::dispatchIndirect(frame.cmd, counters_);
  }
}

}  // namespace vitrine::noodles
