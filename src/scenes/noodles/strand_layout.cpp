#include "scenes/noodles/strand_layout.h"

#include "gpu/check.h"
#include "gpu/device.h"
#include "scenes/noodles/packing.h"

#include <algorithm>
#include <fmt/format.h>
#include <numeric>

namespace vitrine::noodles {

DeviceBudget deviceBudget(const gpu::Device& device) {
  const VkPhysicalDeviceLimits& limits = device.limits();
  DeviceBudget budget;
  budget.deviceName = device.properties().deviceName;
  budget.maxStorageBufferRange = limits.maxStorageBufferRange;
  budget.storageOffsetAlignment = std::max<VkDeviceSize>(limits.minStorageBufferOffsetAlignment, 1);
  budget.maxBufferSize = device.memoryLimits().maxBufferSize;
  budget.deviceLocalHeap = device.memoryLimits().largestDeviceLocalHeap;
  budget.maxGroupCountX = limits.maxComputeWorkGroupCount[0];
  budget.maxGroupCountY = limits.maxComputeWorkGroupCount[1];
  return budget;
}

std::string describeBytes(uint64_t bytes) {
  if (bytes >= (uint64_t(1) << 30)) return fmt::format("{:.2f} GiB", double(bytes) / double(uint64_t(1) << 30));
  if (bytes >= (uint64_t(1) << 20)) return fmt::format("{:.1f} MiB", double(bytes) / double(uint64_t(1) << 20));
  return fmt::format("{:.1f} KiB", double(bytes) / 1024.0);
}

StrandLayout planStrands(glm::uvec3 grid, uint32_t segments, const DeviceBudget& budget,
                         const StrandWorkgroups& workgroups) {
  const uint64_t strands = uint64_t(grid.x) * grid.y * grid.z;
  const std::string what =
      fmt::format("{}x{}x{} strands of {} segments", grid.x, grid.y, grid.z, segments);
  if (strands == 0 || segments == 0) throw Error(what + " is empty: grid and segments must be at least 1.");
  // Instance and strand indices are 32-bit in the shaders (gl_InstanceIndex is even signed).
  if (strands * segments > uint64_t(INT32_MAX))
    throw Error(fmt::format("{} make {} segments; at most {} can be drawn.", what, strands * segments, INT32_MAX));

  StrandLayout layout;
  layout.grid = grid;
  layout.segments = segments;
  layout.strands = uint32_t(strands);
  layout.segmentCount = strands * segments;
  layout.strandBytes = uint64_t(segments + 1) * kNodeBytes;
  layout.bytes = strands * layout.strandBytes;

  if (layout.bytes > budget.maxBufferSize)
    throw Error(fmt::format("{} need {} of segment data; {} allows one buffer of at most {}. Reduce grid or segments.",
                            what, describeBytes(layout.bytes), budget.deviceName, describeBytes(budget.maxBufferSize)));
  // Leave a quarter of the memory for the render targets, the other scenes' leftovers and the driver.
  if (layout.bytes > budget.deviceLocalHeap / 4 * 3)
    throw Error(fmt::format("{} need {} of segment data, more than three quarters of the {} of device memory on {}. "
                            "Reduce grid or segments.",
                            what, describeBytes(layout.bytes), describeBytes(budget.deviceLocalHeap), budget.deviceName));
  if (layout.strandBytes > budget.maxStorageBufferRange)
    throw Error(fmt::format("{}: one strand needs {}, more than the {} one storage binding may cover on {} "
                            "(maxStorageBufferRange). Reduce segments.",
                            what, describeBytes(layout.strandBytes), describeBytes(budget.maxStorageBufferRange),
                            budget.deviceName));

  // Chunks of whole strands whose byte offsets honour the binding alignment.
  const uint64_t alignment = budget.storageOffsetAlignment;
  const uint64_t strandsPerAlignedStep = alignment / std::gcd(layout.strandBytes, alignment);
  uint64_t perChunk = budget.maxStorageBufferRange / layout.strandBytes / strandsPerAlignedStep * strandsPerAlignedStep;
  if (perChunk == 0)
    throw Error(fmt::format("{}: a strand of {} cannot be bound at the {}-byte alignment {} requires. Reduce segments.",
                            what, describeBytes(layout.strandBytes), alignment, budget.deviceName));
  perChunk = std::min<uint64_t>(perChunk, strands);

  for (uint64_t first = 0; first < strands; first += perChunk) {
    StrandChunk chunk;
    chunk.firstStrand = uint32_t(first);
    chunk.strandCount = uint32_t(std::min<uint64_t>(perChunk, strands - first));
    chunk.offset = first * layout.strandBytes;
    chunk.bytes = chunk.strandCount * layout.strandBytes;
    chunk.integrateGroups = groupRows(chunk.strandCount, workgroups.integrate, budget, what);
    chunk.rasterGroups = groupRows(uint64_t(chunk.strandCount) * segments, workgroups.raster, budget, what);
    layout.chunks.push_back(chunk);
  }
  return layout;
}

GroupRows groupRows(uint64_t invocations, uint32_t groupSize, const DeviceBudget& budget, const std::string& what) {
  const uint64_t groups = (invocations + groupSize - 1) / groupSize;
  GroupRows rows{uint32_t(std::min<uint64_t>(groups, budget.maxGroupCountX)), 0};
  const uint64_t y = (groups + rows.x - 1) / std::max(rows.x, 1u);
  if (y > budget.maxGroupCountY)
    throw Error(fmt::format("{}: {} workgroups exceed the compute dispatch limit of {} (maxComputeWorkGroupCount).",
                            what, groups, uint64_t(budget.maxGroupCountX) * budget.maxGroupCountY));
  rows.y = uint32_t(y);
  return rows;
}

}  // namespace vitrine::noodles
