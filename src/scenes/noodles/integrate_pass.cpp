#include "scenes/noodles/integrate_pass.h"

#include "gpu/check.h"

#include <cstddef>

namespace vitrine::noodles {
namespace {

// Mirrors the push block of shaders/noodles/integrate.comp (std430: each vec3 starts a 16-byte slot).
struct IntegratePush {
  glm::vec3 offsetY;
  float spacing;
  glm::vec3 offsetZ;
  float step;
  glm::uvec3 grid;
  uint32_t segments;
  float noiseScale;
  float lift;
  uint32_t firstStrand;
  uint32_t chunkStrands;
  uint32_t field;
  uint32_t integrator;
  uint32_t tangent;
  uint32_t frames;
  uint32_t invocationsPerRow;
};
static_assert(offsetof(IntegratePush, offsetZ) == 16 && offsetof(IntegratePush, grid) == 32 &&
              offsetof(IntegratePush, noiseScale) == 48 && offsetof(IntegratePush, field) == 64 &&
              sizeof(IntegratePush) == 84);

}  // namespace

IntegratePass::IntegratePass(gpu::ProgramLibrary& programs)
    : program_(programs, "noodles/integrate.comp", {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, sizeof(IntegratePush)}) {}

void IntegratePass::record(VkCommandBuffer cmd, const StrandLayout& layout, VkBuffer nodes,
                           const StrandSettings& settings) const {
  if (settings.grid != layout.grid || settings.segments != layout.segments)
    throw Error("noodles: the strand settings and the node buffer disagree on grid or segments");
  program_.bind(cmd);
  IntegratePush push{settings.field.offsetY,
                     settings.spacing,
                     settings.field.offsetZ,
                     settings.step,
                     layout.grid,
                     layout.segments,
                     settings.field.noiseScale,
                     settings.field.lift,
                     0,
                     0,
                     uint32_t(settings.field.kind),
                     uint32_t(settings.integrator),
                     uint32_t(settings.tangent),
                     uint32_t(settings.frames),
                     0};
  for (const StrandChunk& chunk : layout.chunks) {
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    push.invocationsPerRow = chunk.integrateGroups.x * kIntegrateGroupSize;
    program_.push(cmd, gpu::Bindings().storageBuffer(nodes, chunk.offset, chunk.bytes));
    program_.constants(cmd, push);
    vkCmdDispatch(cmd, chunk.integrateGroups.x, chunk.integrateGroups.y, 1);
  }
}

}  // namespace vitrine::noodles
