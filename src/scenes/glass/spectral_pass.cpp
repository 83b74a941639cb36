#include "scenes/glass/spectral_pass.h"

#include "scenes/glass/scene_shape.h"

#include <vector>

namespace vitrine::glass {
namespace {

// The spectral programs' bindings: the frame block, the backdrop and the panorama, the diamond's planes,
// then the colour and motion outputs (compute) or the hull (raster). The shape is specialised.
gpu::ProgramLayout spectralLayout(ShapeKind shape, bool compute) {
  std::vector<VkDescriptorType> bindings{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                         VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER};
  if (compute) bindings.insert(bindings.end(), {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  else bindings.push_back(VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  return {bindings, 0, {int32_t(shape)}};
}

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

const gpu::ComputeProgram& SpectralShadePass::computeProgram(ShapeKind shape) {
  auto& program = compute_[size_t(shape)];
  if (!program)
    program = std::make_unique<gpu::ComputeProgram>(programs_, "glass/spectral.comp", spectralLayout(shape, true));
  return *program;
}

const gpu::GraphicsProgram& SpectralShadePass::rasterProgram(ShapeKind shape) {
  auto& program = raster_[size_t(shape)];
  if (!program) program = std::make_unique<gpu::GraphicsProgram>(programs_, proxyState(), spectralLayout(shape, false));
  return *program;
}

void SpectralShadePass::record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
                               DiamondBuffers& diamond, SpectralPass path, ShapeKind shape, VkExtent2D extent) {
  const bool compute = path == SpectralPass::Compute;
  const gpu::ImageUse sampled = compute ? gpu::use::ComputeSample : gpu::use::FragmentSample;
  frame.transition(sources.backdrop, sampled);
  frame.transition(sources.panorama, sampled);
  frame.transition(diamond.planes(), compute ? gpu::use::ComputeReadBuffer : gpu::use::FragmentReadBuffer);
  gpu::Bindings bindings = sources.bindings(frame.device);
  bindings.storageBuffer(diamond.planes().handle());
  gpu::Image& colour = frame.image(images.colour);
  gpu::Image& motion = frame.image(images.motion);
  if (compute) {
    frame.transition(colour, gpu::use::ComputeWrite);
    frame.transition(motion, gpu::use::ComputeWrite);
    const gpu::ComputeProgram& program = computeProgram(shape);
    program.bind(frame.cmd);
    program.push(frame.cmd, bindings.storageImage(colour.view()).storageImage(motion.view()));
    program.dispatchOver(frame.cmd, extent, {8, 8});
    return;
  }
  frame.transition(diamond.hull(), gpu::use::VertexReadBuffer);
  gpu::RenderingDesc desc;
  desc.colors = {{&colour, VkClearColorValue{}}, {&motion, VkClearColorValue{}}};
  desc.depth = gpu::DepthAttachment{&frame.image(images.depth)};
  const auto rendering = frame.rendering(desc);
  const gpu::GraphicsProgram& program = rasterProgram(shape);
  program.bind(frame.cmd);
  program.push(frame.cmd, bindings.storageBuffer(diamond.hull().handle()));
  const uint32_t vertices = shape == ShapeKind::Diamond ? diamond.hullVertices() : 36u;  // the hull, or a box
  vkCmdDraw(frame.cmd, vertices, uint32_t(instanceCount(shape)), 0, 0);
}

}  // namespace vitrine::glass
