#include "scenes/noodles/tube_pass.h"

#include "gpu/barriers.h"

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

// How the attachments were last used: by the previous frame's pass, whose contents are not kept.
constexpr gpu::ImageUse kPreviousDepth{VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                           VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                                       VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
constexpr gpu::ImageUse kPreviousColour{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED};

}  // namespace

TubePass::TubePass(const gpu::Device& device, gpu::ProgramLibrary& programs)
    : device_(device),
      single_(programs, tubeState(VK_SAMPLE_COUNT_1_BIT), kTubeLayout),
      multisampled_(programs, tubeState(VK_SAMPLE_COUNT_4_BIT), kTubeLayout) {}

void TubePass::ensureAttachments(VkExtent2D extent, VkSampleCountFlagBits samples) {
  const bool sized = depth_ && depth_.extent2d().width == extent.width && depth_.extent2d().height == extent.height;
  if (sized && depth_.desc().samples == samples) return;
  if (depth_) device_.waitIdle();  // the previous frame may still be drawing into them

  gpu::ImageDesc depth;
  depth.extent = {extent.width, extent.height, 1};
  depth.format = kDepthFormat;
  depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depth.samples = samples;
  depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  depth_ = gpu::Image(device_, depth, "noodles depth");

  colour_ = {};
  if (samples == VK_SAMPLE_COUNT_1_BIT) return;
  gpu::ImageDesc colour;
  colour.extent = depth.extent;
  colour.format = kColourFormat;
  colour.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
  colour.samples = samples;
  colour_ = gpu::Image(device_, colour, "noodles msaa colour");
}

void TubePass::record(VkCommandBuffer cmd, const RenderTarget& target, const StrandLayout& layout, VkBuffer nodes,
                      const TubeView& view) {
  const VkSampleCountFlagBits samples = view.msaa ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
  ensureAttachments(target.extent, samples);
  gpu::transition(cmd, depth_.handle(), kPreviousDepth, gpu::use::DepthAttachment, VK_IMAGE_ASPECT_DEPTH_BIT);
  if (colour_) gpu::transition(cmd, colour_.handle(), kPreviousColour, gpu::use::ColorAttachment);

  VkRenderingAttachmentInfo colour{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  colour.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colour.clearValue.color = {{kBackground.r, kBackground.g, kBackground.b, 1.0f}};
  if (colour_) {  // draw multisampled, average into the target, keep nothing else
    colour.imageView = colour_.view();
    colour.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    colour.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    colour.resolveImageView = target.view;
    colour.resolveImageLayout = VK_IMAGE_LAYOUT_GENERAL;
    colour.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  } else {
    colour.imageView = target.view;
    colour.imageLayout = VK_IMAGE_LAYOUT_GENERAL;
    colour.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = depth_.view();
  depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {0.0f, 0};  // reverse-Z: 0 is infinitely far

  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, target.extent};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &colour;
  rendering.pDepthAttachment = &depth;
  vkCmdBeginRendering(cmd, &rendering);

  const VkViewport viewport{0.0f, 0.0f, float(target.extent.width), float(target.extent.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, target.extent};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  const gpu::GraphicsProgram& program = colour_ ? multisampled_ : single_;
  program.bind(cmd);
  TubePush push{view.viewProjection, view.eye, view.radius, 0, 0, layout.strands, uint32_t(view.colouring),
                layout.segments, view.stripe ? 1u : 0u};
  for (const StrandChunk& chunk : layout.chunks) {
    push.firstStrand = chunk.firstStrand;
    push.chunkStrands = chunk.strandCount;
    program.push(cmd, gpu::Bindings().storageBuffer(nodes, chunk.offset, chunk.bytes));
    program.constants(cmd, push);
    vkCmdDraw(cmd, kTubeStripVertices, chunk.strandCount * layout.segments, 0, 0);
  }
  vkCmdEndRendering(cmd);
}

}  // namespace vitrine::noodles
