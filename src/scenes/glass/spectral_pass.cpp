#include "scenes/glass/spectral_pass.h"

#include "scenes/glass/scene_shape.h"

namespace vitrine::glass {
namespace {

gpu::GraphicsState proxyState() {
  gpu::GraphicsState state;
  state.vertex = "glass/proxy.vert";
  state.fragment = "glass/glass.frag";
  state.colorFormats = {kColourFormat, kMotionFormat};
  state.depthFormat = kDepthFormat;
  state.cull = VK_CULL_MODE_FRONT_BIT;  // back faces: one fragment per covered pixel, even from inside
  return state;
}

}  // namespace

SpectralShadePass::SpectralShadePass(gpu::ProgramLibrary& programs)
    : compute_(programs, "glass/spectral.comp"), raster_(programs, proxyState()) {}

void SpectralShadePass::record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
                               const DiamondBuffers& diamond, SpectralPass path, ShadeVariant variant, VkExtent2D extent) const {
  const bool compute = path == SpectralPass::Compute;
  const gpu::ImageUse sampled = compute ? gpu::use::ComputeSample : gpu::use::FragmentSample;
  frame.transition(sources.backdrop, sampled);
  frame.transition(sources.panorama, sampled);
  gpu::Buffer& planes = frame.buffer(diamond.planes());
  frame.transition(planes, compute ? gpu::use::ComputeReadBuffer : gpu::use::FragmentReadBuffer);
  gpu::Bindings bindings = sources.bindings(frame.device);
  bindings.storageBuffer("DiamondPlanes", planes.handle());
  gpu::Image& colour = frame.image(images.colour);
  gpu::Image& motion = frame.image(images.motion);
  if (compute) {
    frame.transition(colour, gpu::use::ComputeWrite);
    frame.transition(motion, gpu::use::ComputeWrite);
    const gpu::ComputeProgram& program = compute_({int32_t(variant.shape), int32_t(variant.options)});
    program.bind(frame.cmd);
    program.push(frame.cmd, bindings.storageImage("colourOut", colour.view()).storageImage("motionOut", motion.view()));
    program.dispatchOver(frame.cmd, extent);
    return;
  }
  gpu::Buffer& hull = frame.buffer(diamond.hull());
  frame.transition(hull, gpu::use::VertexReadBuffer);
  gpu::RenderingDesc desc;
  desc.colors = {{&colour, VkClearColorValue{}}, {&motion, VkClearColorValue{}}};
  desc.depth = gpu::DepthAttachment{&frame.image(images.depth)};
  const auto rendering = frame.rendering(desc);
  const gpu::GraphicsProgram& program = raster_({int32_t(variant.shape), int32_t(variant.options)});
  program.bind(frame.cmd);
  program.push(frame.cmd, bindings.storageBuffer("Hull", hull.handle()));
  const uint32_t vertices = variant.shape == ShapeKind::Diamond ? diamond.hullVertices() : 36u;  // the hull, or a box
  vkCmdDraw(frame.cmd, vertices, uint32_t(instanceCount(variant.shape)), 0, 0);
}

}  // namespace vitrine::glass
