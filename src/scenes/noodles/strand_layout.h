#pragma once
// How much GPU memory the strands take and how they are split for binding. Sizes come from the
// parameters (grid and segments) and are checked against the device before anything is allocated,
// so an impossible request is a vitrine::Error that says which limit it hits, not a lost device.
// One storage-buffer binding may cover at most maxStorageBufferRange bytes (128 MiB on lavapipe and
// some GPUs), so the node buffer is bound in chunks of whole strands, each one dispatch and one draw.
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace vitrine::gpu {
class Device;
}

namespace vitrine::noodles {

// The device limits that bound the strand buffer.
struct DeviceBudget {
  std::string deviceName;
  uint64_t maxStorageBufferRange = 0;
  uint64_t storageOffsetAlignment = 1;  // minStorageBufferOffsetAlignment
  uint64_t maxBufferSize = 0;           // the smaller of maintenance4's maxBufferSize and maxMemoryAllocationSize
  uint64_t deviceLocalHeap = 0;         // the largest device-local heap
  uint32_t maxGroupCountX = 0, maxGroupCountY = 0;
};

DeviceBudget deviceBudget(const gpu::Device& device);

// The workgroup sizes the dispatches are counted in, as the shaders declare them (their programs'
// localSize): integrate.comp runs one invocation a strand, raster.comp one a segment, both in
// one-dimensional workgroups.
struct StrandWorkgroups {
  uint32_t integrate = 0;
  uint32_t raster = 0;
};

// A 1D dispatch laid out in rows of workgroups, for counts past maxComputeWorkGroupCount[0]: x
// workgroups a row, y rows; a shader finds its index as row * (x * group size) + column.
struct GroupRows {
  uint32_t x = 0, y = 0;
};

// `invocations` in workgroups of `groupSize`, in rows when one row cannot hold them; throws
// vitrine::Error naming `what` past the device's dispatch limits.
GroupRows groupRows(uint64_t invocations, uint32_t groupSize, const DeviceBudget& budget, const std::string& what);

struct StrandChunk {
  uint32_t firstStrand = 0;
  uint32_t strandCount = 0;
  uint64_t offset = 0;  // bytes into the node buffer
  uint64_t bytes = 0;
  GroupRows integrateGroups;  // one invocation a strand
  GroupRows rasterGroups;     // one invocation a segment
};

struct StrandLayout {
  glm::uvec3 grid{0};
  uint32_t segments = 0;
  uint32_t strands = 0;
  uint64_t segmentCount = 0;  // strands * segments: the tube instances drawn
  uint64_t strandBytes = 0;   // (segments + 1) nodes
  uint64_t bytes = 0;         // the whole node buffer
  std::vector<StrandChunk> chunks;
};

// Throws vitrine::Error naming the limit when the strands cannot fit.
StrandLayout planStrands(glm::uvec3 grid, uint32_t segments, const DeviceBudget& budget,
                         const StrandWorkgroups& workgroups);

std::string describeBytes(uint64_t bytes);  // "162.5 MiB"

}  // namespace vitrine::noodles
