#pragma once
// The compute passes that integrate every strand into the node buffer, one invocation per strand and
// one dispatch per chunk (strand_layout.h), in the exact flow or in a bake of it (field_bake.h),
// and the pass that bakes the flow. The caller owns the node buffer, the volume and their barriers.
#include "gpu/program_variants.h"
#include "scenes/noodles/strand.h"
#include "scenes/noodles/strand_layout.h"

namespace vitrine::noodles {

// The baked flow as integrate_baked.comp reads it: texel by texel, weighed in the shader (sampleBake).
struct BakedFlow {
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
};

inline constexpr VkFormat kBakedFlowFormat = VK_FORMAT_A2B10G10R10_UNORM_PACK32;  // kBakeRange says why
inline constexpr VkFormat kBakedFlowStorageFormat = VK_FORMAT_R32_UINT;           // bake.comp writes the bits

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
  // integrate_strands.glsl's local size (checked against the shader's each time a program is taken).
  static constexpr uint32_t kWorkgroupSize = 64;
  // The program for a flow source (exact, baked), specialised on the options integrate_strands.glsl
  // takes as constants (the field, the integrator, the tangent, the frames).
  const gpu::ComputeProgram& integrateProgram(bool baked, const StrandSettings& settings) const;

  gpu::ComputeVariants exact_, baked_;
  gpu::ComputeVariants bake_;  // bake.comp, specialised on the field
};

}  // namespace vitrine::noodles
