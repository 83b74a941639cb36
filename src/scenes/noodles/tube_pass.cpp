#include "scenes/noodles/tube_pass.h"


#include <cstddef>

namespace vitrine::noodles {
namespace {

// Mirrors shaders/noodles/tube_push.glsl.
struct TubePush {
  glm::mat4 viewProjection;
  glm::vec3 eye;
  float radius;
  uint32_t firstStrand;
  uint32_t chunkStrands;
  uint32_t strands;
  uint32_t colouring;
  uint32_t segments;
  uint32_t stripe;
};
static_assert(offsetof(TubePush, eye) == 64 && offsetof(TubePush, firstStrand) == 80 && sizeof(TubePush) == 104);

constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
constexpr VkFormat kColourFormat = VK_FORMAT_R16G16B16A16_SFLOAT;  // the target's

gpu::GraphicsState tubeState(VkSampleCountFlagBits samples) {
  gpu::GraphicsState state;
  state.vertex = "noodles/tube.vert";
  state.fragment = "noodles/tube.frag";
  state.colorFormats = {kColourFormat};
  state.depthFormat = kDepthFormat;
  state.samples = samples;
  state.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
  state.cull = VK_CULL_MODE_BACK_BIT;  // the tubes are closed as seen from outside
  return state;
}

const gpu::ProgramLayout kTubeLayout{{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, sizeof(TubePush)};

gpu::ImageDecl depthDecl(VkSampleCountFlagBits samples) {
  gpu::ImageDecl depth;
  depth.name = "noodles depth";
  depth.format = kDepthFormat;
  depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depth.samples = samples;
  return depth;
}

gpu::ImageDecl colourDecl(VkSampleCountFlagBits samples) {
  gpu::ImageDecl colour;
  colour.name = "noodles msaa colour";
  colour.format = kColourFormat;
  colour.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  colour.samples = samples;
  // Without MSAA the tubes draw straight into the target: a 1x1 stand-in costs nothing.
  colour.size = samples != VK_SAMPLE_COUNT_1_BIT ? gpu::ImageSize::relative(1.0f) : gpu::ImageSize::absolute(1, 1);
  return colour;
}

}  // namespace

TubePass::TubePass(const SceneContext& context)
    : resources_(context.resources),
      single_(context.programs, tubeState(VK_SAMPLE_COUNT_1_BIT), kTubeLayout),
      multisampled_(context.programs, tubeState(VK_SAMPLE_COUNT_4_BIT), kTubeLayout),
      depth_(resources_.declare(depthDecl(samples_))),
      colour_(resources_.declare(colourDecl(samples_))) {}

void TubePass::record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, const TubeView& view) {
  const VkSampleCountFlagBits samples = view.msaa ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
  if (samples != samples_) {  // the old attachments are retired behind the frames still using them
    samples_ = samples;
    resources_.redeclare(depth_, depthDecl(samples));
    resources_.redeclare(colour_, colourDecl(samples));
  }
  const VkClearColorValue background{{kBackground.r, kBackground.g, kBackground.b, 1.0f}};
  gpu::RenderingDesc desc;
  if (view.msaa)  // draw multisampled, average into the target, keep nothing else
    desc.colors = {{&frame.image(colour_), background, &frame.target, false}};
  else
    desc.colors = {{&frame.target, background}};
  desc.depth = gpu::DepthAttachment{&frame.image(depth_)};
  const auto rendering = frame.rendering(desc);

  const gpu::GraphicsProgram& program = view.msaa ? multisampled_ : single_;
  program.bind(frame.cmd);
  TubePush push{view.viewProjection, view.eye, view.radius, 0, 0, layout.strands, uint32_t(view.colouring),
                layout.segments, view.stripe ? 1u : 0u};
  for (const StrandChunk& chunk : layout.chunks) {
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    program.push(frame.cmd, gpu::Bindings().storageBuffer(nodes, chunk.offset, chunk.bytes));
    program.constants(frame.cmd, push);
    vkCmdDraw(frame.cmd, kTubeStripVertices, chunk.strandCount * layout.segments, 0, 0);
  }
}

}  // namespace vitrine::noodles
