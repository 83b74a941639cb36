#include "scenes/noodles/integrate_pass.h"

#include "core/error.h"
#include "gpu/barriers.h"
#include "shaders/noodles/integrate_push.h"

namespace vitrine::noodles {

IntegratePass::IntegratePass(gpu::ProgramLibrary& programs)
    : exact_(programs, "noodles/integrate.comp"),
      baked_(programs, "noodles/integrate_baked.comp"),
      bake_(programs, "noodles/bake.comp") {}

const gpu::ComputeProgram& IntegratePass::integrateProgram(bool baked, const StrandSettings& settings) const {
  // integrate_strands.glsl's constant_id 0..3. The baked pass reads its field and integrator from the
  // push block (specialised, the H200 ran its RK4 a third slower), so its variants differ only in the
  // tangent and the frames.
  const int32_t tangent = int32_t(settings.tangent), frames = int32_t(settings.frames);
  const gpu::ComputeProgram& program =
      baked ? baked_({0, 0, tangent, frames})
            : exact_({int32_t(settings.field.kind), int32_t(settings.integrator), tangent, frames});
  if (program.localSize()[0] != kWorkgroupSize) throw Error("noodles: the integrate shader's local size changed");
  return program;
}

void IntegratePass::recordBake(VkCommandBuffer cmd, const StrandSettings& settings, VkImageView volume) const {
  if (!settings.bake.baked()) throw Error("noodles: asked to bake a flow the settings do not bake");
  const gpu::ComputeProgram& bake = bake_({int32_t(settings.field.kind)});
  bake.bind(cmd);
  bake.push(cmd, gpu::Bindings().storageImage("bakedFlow", volume));
  bake.constants(cmd, shader::NoodlesBakePush{.offsetY = settings.field.offsetY,
                                              .noiseScale = settings.field.noiseScale,
                                              .offsetZ = settings.field.offsetZ,
                                              .origin = settings.bake.origin,
                                              .spacing = settings.bake.spacing,
                                              .range = kBakeRange});
  const glm::uvec3 n = settings.bake.texels;
  bake.dispatchOver(cmd, VkExtent3D{n.x, n.y, n.z});
}

void IntegratePass::record(VkCommandBuffer cmd, const StrandLayout& layout, VkBuffer nodes,
                           const StrandSettings& settings, const BakedFlow& baked) const {
  if (settings.grid != layout.grid || settings.segments != layout.segments)
    throw Error("noodles: the strand settings and the node buffer disagree on grid or segments");
  const bool bakedFlow = settings.bake.baked();
  if (bakedFlow && baked.view == VK_NULL_HANDLE) throw Error("noodles: the strands follow a baked flow not given");
  const gpu::ComputeProgram& program = integrateProgram(bakedFlow, settings);
  program.bind(cmd);
  shader::NoodlesIntegratePush push{.offsetY = settings.field.offsetY,
                                    .spacing = settings.spacing,
                                    .offsetZ = settings.field.offsetZ,
                                    .step = settings.step,
                                    .grid = layout.grid,
                                    .segmentsPerStrand = layout.segments,
                                    .noiseScale = settings.field.noiseScale,
                                    .lift = settings.field.lift,
                                    .fieldKind = uint32_t(settings.field.kind),
                                    .integrator = uint32_t(settings.integrator)};
  if (bakedFlow) {
    push.bakeOrigin = settings.bake.origin;
    push.bakeInverseSpacing = 1.0f / settings.bake.spacing;
    push.bakeLastTexel = glm::vec3(settings.bake.texels - 1u);
    push.bakeRange = kBakeRange;
  }
  for (const StrandChunk& chunk : layout.chunks) {
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    push.invocationsPerRow = chunk.integrateGroups.x * workgroupSize();
    gpu::Bindings bindings;
    bindings.storageBuffer("Nodes", nodes, chunk.offset, chunk.bytes);
    if (bakedFlow) bindings.sampledImage("bakedFlow", baked.view, baked.sampler, gpu::use::ComputeSample.layout);
    program.push(cmd, bindings);
    program.constants(cmd, push);
    program.dispatchGroups(cmd, {chunk.integrateGroups.x, chunk.integrateGroups.y, 1});
  }
}

}  // namespace vitrine::noodles
