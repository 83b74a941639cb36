#include "gpu/rendering.h"

#include "core/error.h"

#include <array>

namespace vitrine::gpu {

Rendering::Rendering(VkCommandBuffer cmd, const RenderingDesc& desc) : cmd_(cmd) {
  const Image* first = !desc.colors.empty() ? desc.colors[0].image : desc.depth ? desc.depth->image : nullptr;
  if (!first) throw Error("a rendering pass needs at least one attachment");
  extent_ = first->extent2d();

  constexpr size_t kMaxColors = 8;
  if (desc.colors.size() > kMaxColors) throw Error("more colour attachments than a rendering pass takes");
  std::array<VkRenderingAttachmentInfo, kMaxColors> colors{};
  uint32_t colorCount = 0;
  for (const ColorAttachment& c : desc.colors) {
    if (c.clear) c.image->discard();  // cleared: the old contents are not read
    c.image->use(cmd, use::ColorAttachment);
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = c.image->view();
    info.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    info.loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    if (c.clear) info.clearValue.color = *c.clear;
    info.storeOp = c.store ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    if (c.resolve) {
      c.resolve->discard();  // every texel is written by the resolve
      c.resolve->use(cmd, use::ColorAttachment);  // resolves write in the colour-output stage
      info.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
      info.resolveImageView = c.resolve->view();
      info.resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
      extent_ = c.resolve->extent2d();
    }
    colors[colorCount++] = info;
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  if (desc.depth) {
    if (desc.depth->clear) desc.depth->image->discard();
    desc.depth->image->use(cmd, use::DepthAttachment);
    depth.imageView = desc.depth->image->view();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = desc.depth->clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    if (desc.depth->clear) depth.clearValue.depthStencil = {*desc.depth->clear, 0};
    depth.storeOp = desc.depth->store ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
  }

  VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
  rendering.renderArea = {{0, 0}, extent_};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = colorCount;
  rendering.pColorAttachments = colors.data();
  rendering.pDepthAttachment = desc.depth ? &depth : nullptr;
  vkCmdBeginRendering(cmd, &rendering);

  const VkViewport viewport{0.0f, 0.0f, float(extent_.width), float(extent_.height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, extent_};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
}

Rendering::~Rendering() { vkCmdEndRendering(cmd_); }

}  // namespace vitrine::gpu
