#include "host/scene_renderer.h"

#include "gpu/barriers.h"

#include <algorithm>
#include <cmath>

namespace vitrine::host {

SceneRenderer::SceneRenderer(const gpu::Device& device, gpu::ProgramLibrary& programs, uint32_t framesInFlight)
    : device_(device), programs_(programs), framesInFlight_(framesInFlight), timer_(device, framesInFlight) {}

void SceneRenderer::setScene(const SceneInfo& info) {
  scene_.reset();  // release the old scene's GPU objects before the new one allocates
  target_ = {};
  scene_ = info.create(SceneContext{device_, programs_, framesInFlight_});
  info_ = &info;
}

void SceneRenderer::ensureTarget(VkExtent2D output) {
  const float scale = std::clamp(scene_->renderScale(), 0.1f, 1.0f);
  const VkExtent2D wanted{std::max(1u, static_cast<uint32_t>(std::lround(output.width * scale))),
                          std::max(1u, static_cast<uint32_t>(std::lround(output.height * scale)))};
  if (target_ && target_.extent2d().width == wanted.width && target_.extent2d().height == wanted.height) return;
  if (target_) device_.waitIdle();  // the old target may still be read by a frame in flight
  gpu::ImageDesc desc;
  desc.extent = {wanted.width, wanted.height, 1};
  desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
               VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  target_ = gpu::Image(device_, desc, "HDR target");
  scene_->resize(wanted);
}

void SceneRenderer::record(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, const BlitDestination& dst) {
  ensureTarget(dst.extent);
  timer_.beginFrame(cmd, slot);
  const RenderTarget target{target_.handle(), target_.view(), target_.extent2d(), target_.desc().format};

  // The previous frame's blit read the target; its contents are not kept.
  const gpu::ImageUse previous{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
  const gpu::ImageUse drawing{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                              VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                  VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
                              VK_IMAGE_LAYOUT_GENERAL};
  gpu::transition(cmd, target.image, previous, drawing);
  scene_->record(FrameContext{device_, cmd, &timer_, target, input, slot});

  gpu::Pass pass(device_, &timer_, cmd, "present blit");
  gpu::transition(cmd, target.image, drawing, gpu::use::TransferSrc);
  gpu::transition(cmd, dst.image, dst.before, gpu::use::TransferDst);
  const VkExtent2D src = target.extent;
  VkImageBlit2 region{VK_STRUCTURE_TYPE_IMAGE_BLIT_2};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {static_cast<int32_t>(src.width), static_cast<int32_t>(src.height), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[1] = {static_cast<int32_t>(dst.extent.width), static_cast<int32_t>(dst.extent.height), 1};
  VkBlitImageInfo2 blit{VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2};
  blit.srcImage = target.image;
  blit.srcImageLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  blit.dstImage = dst.image;
  blit.dstImageLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  blit.regionCount = 1;
  blit.pRegions = &region;
  const bool sameSize = src.width == dst.extent.width && src.height == dst.extent.height;
  blit.filter = sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  vkCmdBlitImage2(cmd, &blit);
  gpu::transition(cmd, dst.image, gpu::use::TransferDst, dst.after);
}

}  // namespace vitrine::host
