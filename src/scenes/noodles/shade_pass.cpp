#include "scenes/noodles/shade_pass.h"

#include "gpu/buffer_commands.h"

namespace vitrine::noodles {

ShadePass::ShadePass(gpu::ProgramLibrary& programs)
    : program_(
          programs, "noodles/shade.comp",
          {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
           sizeof(RasterPush)}) {}

void ShadePass::record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, gpu::Buffer& visibility,
                       uint32_t samplesPerAxis, const TubeView& view) const {
  visibility.use(frame.cmd, gpu::use::ComputeReadBuffer);
  RasterPush push = rasterPush(view, layout, samplesPerAxis);
  program_.bind(frame.cmd);
  for (size_t i = 0; i < layout.chunks.size(); ++i) {
    const StrandChunk& chunk = layout.chunks[i];
    // The first chunk writes every pixel; later ones read it back and add theirs.
    frame.transition(frame.target, i == 0 ? gpu::use::ComputeWrite : gpu::use::ComputeReadWrite);
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    push.accumulate = i == 0 ? 0u : 1u;
    program_.push(frame.cmd, gpu::Bindings()
                                 .storageBuffer(nodes, chunk.offset, chunk.bytes)
                                 .storageBuffer(visibility.handle())
                                 .storageImage(frame.target.view()));
    program_.constants(frame.cmd, push);
    program_.dispatchOver(frame.cmd, frame.target.extent2d(), {8, 8});
  }
}

}  // namespace vitrine::noodles
