#include "scenes/noodles/integrate_pass.h"

#include "core/error.h"
#include "shaders/noodles/integrate_push.h"

namespace vitrine::noodles {

IntegratePass::IntegratePass(gpu::ProgramLibrary& programs) : program_(programs, "noodles/integrate.comp") {}

void IntegratePass::record(VkCommandBuffer cmd, const StrandLayout& layout, VkBuffer nodes,
                           const StrandSettings& settings) const {
  if (settings.grid != layout.grid || settings.segments != layout.segments)
    throw Error("noodles: the strand settings and the node buffer disagree on grid or segments");
  program_.bind(cmd);
  shader::NoodlesIntegratePush push{.offsetY = settings.field.offsetY,
                                    .spacing = settings.spacing,
                                    .offsetZ = settings.field.offsetZ,
                                    .step = settings.step,
                                    .grid = layout.grid,
                                    .segmentsPerStrand = layout.segments,
                                    .noiseScale = settings.field.noiseScale,
                                    .lift = settings.field.lift,
                                    .fieldKind = uint32_t(settings.field.kind),
                                    .integrator = uint32_t(settings.integrator),
                                    .tangentMode = uint32_t(settings.tangent),
                                    .frameMethod = uint32_t(settings.frames)};
  for (const StrandChunk& chunk : layout.chunks) {
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    push.invocationsPerRow = chunk.integrateGroups.x * workgroupSize();
    program_.push(cmd, gpu::Bindings().storageBuffer("Nodes", nodes, chunk.offset, chunk.bytes));
    program_.constants(cmd, push);
    program_.dispatchGroups(cmd, {chunk.integrateGroups.x, chunk.integrateGroups.y, 1});
  }
}

}  // namespace vitrine::noodles
