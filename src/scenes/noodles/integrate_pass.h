#pragma once
// The compute pass that integrates every strand into the node buffer, one invocation per strand and
// one dispatch per chunk (strand_layout.h). The caller owns the node buffer and its barriers.
#include "gpu/program.h"
#include "scenes/noodles/strand.h"
#include "scenes/noodles/strand_layout.h"

namespace vitrine::noodles {

class IntegratePass {
 public:
  explicit IntegratePass(gpu::ProgramLibrary& programs);
  void record(VkCommandBuffer cmd, const StrandLayout& layout, VkBuffer nodes, const StrandSettings& settings) const;
  uint32_t workgroupSize() const { return program_.localSize()[0]; }  // strands a workgroup integrates

 private:
  gpu::ComputeProgram program_;
};

}  // namespace vitrine::noodles
