#include "scenes/noodles/shade_pass.h"

#include "shaders/noodles/raster_blocks.h"

namespace vitrine::noodles {

void ShadePass::record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, gpu::Buffer& visibility,
                       uint32_t samplesPerAxis, const TubeView& view) const {
  frame.transition(visibility, gpu::use::ComputeReadBuffer);
  shader::NoodlesRasterPush push = rasterPush(view, layout);
  const gpu::ComputeProgram& program = bySamples_({int32_t(samplesPerAxis)});
  program.bind(frame.cmd);
  for (size_t i = 0; i < layout.chunks.size(); ++i) {
    const StrandChunk& chunk = layout.chunks[i];
    // The first chunk writes every pixel; later ones read it back and add theirs.
    frame.transition(frame.target, i == 0 ? gpu::use::ComputeWrite : gpu::use::ComputeReadWrite);
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    push.accumulate = i == 0 ? 0u : 1u;
    program.push(frame.cmd, gpu::Bindings()
                                 .storageBuffer("Nodes", nodes, chunk.offset, chunk.bytes)
                                 .storageBuffer("Visibility", visibility.handle())
                                 .storageImage("target", frame.target.view()));
    program.constants(frame.cmd, push);
    program.dispatchOver(frame.cmd, frame.target.extent2d());
  }
}

}  // namespace vitrine::noodles
