#pragma once
// The compute passes that integrate every strand into the node buffer, one invocation per strand and
// one dispatch per chunk (strand_layout.h), in the exact flow or in a bake of it (field_bake.h),
// and the pass that bakes the flow. The caller owns the node buffer, the volume and their barriers.
#include "gpu/program.h"
#include "scenes/noodles/strand.h"
#include "scenes/noodles/strand_layout.h"

#include <array>
#include <memory>

namespace vitrine::noodles {

// The baked flow as integrate_baked.comp samples it (linear filter, clamped).
struct BakedFlow {
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};

inline constexpr VkFormat kBakedFlowFormat = VK_FORMAT_A2B10G10R10_UNORM_PACK32;  // kBakeRange says why

class IntegratePass {
 public:
  explicit IntegratePass(gpu::ProgramLibrary& programs);
  // Writes settings.bake's texels (settings.bake.baked() must hold) into `volume`, a storage image.
  void recordBake(VkCommandBuffer cmd, const StrandSettings& settings, VkImageView volume) const;
  // Integrates every strand; `baked` is the volume recordBake filled, needed when settings.bake is baked.
  void record(VkCommandBuffer cmd, const StrandLayout& layout, VkBuffer nodes, const StrandSettings& settings,
              const BakedFlow& baked = {}) const;
  uint32_t workgroupSize() const { return kWorkgroupSize; }  // strands a workgroup integrates

 private:
  // integrate_strands.glsl's local size (checked against the shader when a program is built).
  static constexpr uint32_t kWorkgroupSize = 64;
  // One program a flow source (exact, baked) and combination of the options that specialise it (the
  // field, the integrator, the tangent, the frames), and a bake a field; built when first used.
  const gpu::ComputeProgram& integrateProgram(bool baked, const StrandSettings& settings) const;
  const gpu::ComputeProgram& bakeProgram(maths::FieldKind field) const;

  gpu::ProgramLibrary& programs_;
  mutable std::array<std::unique_ptr<gpu::ComputeProgram>, 2 * 16> integrate_;
  mutable std::array<std::unique_ptr<gpu::ComputeProgram>, 2> bake_;
};

}  // namespace vitrine::noodles
