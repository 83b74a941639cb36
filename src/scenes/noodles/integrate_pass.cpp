#include "scenes/noodles/integrate_pass.h"

#include "core/error.h"
#include "gpu/barriers.h"
#include "shaders/noodles/integrate_push.h"

namespace vitrine::noodles {

IntegratePass::IntegratePass(gpu::ProgramLibrary& programs) : programs_(programs) {}

const gpu::ComputeProgram& IntegratePass::integrateProgram(bool baked, const StrandSettings& settings) const {
  // integrate_strands.glsl's constant_id 0..3, each a bit of the index. The baked pass reads its field
  // and integrator from the push block, so its pipelines differ only in the tangent and the frames.
  const std::array<uint32_t, 4> options{baked ? 0u : uint32_t(settings.field.kind),
                                        baked ? 0u : uint32_t(settings.integrator), uint32_t(settings.tangent),
                                        uint32_t(settings.frames)};
  size_t index = baked ? 16 : 0;
  for (size_t i = 0; i < options.size(); ++i) index |= size_t(options[i] & 1u) << i;
  auto& program = integrate_[index];
  if (!program) {
    gpu::ProgramOptions specialised;
    for (uint32_t option : options) specialised.specialization.push_back(int32_t(option));
    program = std::make_unique<gpu::ComputeProgram>(
        programs_, baked ? "noodles/integrate_baked.comp" : "noodles/integrate.comp", specialised);
    if (program->localSize()[0] != kWorkgroupSize) throw Error("noodles: the integrate shader's local size changed");
  }
  return *program;
}

const gpu::ComputeProgram& IntegratePass::bakeProgram(maths::FieldKind field) const {
  auto& program = bake_[size_t(field)];
  if (!program)
    program = std::make_unique<gpu::ComputeProgram>(programs_, "noodles/bake.comp",
                                                    gpu::ProgramOptions{.specialization = {int32_t(field)}});
  return *program;
}

void IntegratePass::recordBake(VkCommandBuffer cmd, const StrandSettings& settings, VkImageView volume) const {
  if (!settings.bake.baked()) throw Error("noodles: asked to bake a flow the settings do not bake");
  const gpu::ComputeProgram& bake = bakeProgram(settings.field.kind);
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
