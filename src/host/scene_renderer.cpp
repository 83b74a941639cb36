#include "host/scene_renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "gpu/barriers.h"
#include "gpu/check.h"

namespace vitrine::host {
namespace {
// How the target is used while the scene draws: compute writes and colour attachments.
constexpr gpu::ImageUse kDrawing{
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT,
    VK_IMAGE_LAYOUT_GENERAL};
}  // namespace

SceneRenderer::SceneRenderer(const gpu::Device& device, gpu::ProgramLibrary& programs, uint32_t framesInFlight)
    : device_(device),
      programs_(programs),
      framesInFlight_(framesInFlight),
      timer_(device, framesInFlight),
      present_(programs, "host/present.comp",
               {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(uint32_t)}) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_LINEAR;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  VkSampler sampler;
  VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
  sampler_ = gpu::Unique<VkSampler>(device, sampler);
  device.name(sampler, VK_OBJECT_TYPE_SAMPLER, "present sampler");
}

void SceneRenderer::setScene(const SceneInfo& info) {
  scene_.reset();  // release the old scene's GPU objects before the new one allocates
  target_ = {};
  scene_ = info.create(SceneContext{device_, programs_, framesInFlight_});
  info_ = &info;
}

void SceneRenderer::applyParameters(const std::vector<std::pair<std::string, std::string>>& parameters) {
  for (const auto& [key, value] : parameters) {
    std::string why;
    if (!scene_->setParameter(key, value, &why))
      throw Error(fmt::format("Scene {} rejects {}={}: {}", info_->name, key, value, why));
  }
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

  // Last frame's present or blit, and any screenshot copy, read the target; its contents are not kept.
  const gpu::ImageUse previous{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                               VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
  gpu::transition(cmd, target.image, previous, kDrawing);
  scene_->record(FrameContext{device_, cmd, &timer_, target, input, slot});
  if (dst.storageView && device_.storageWriteWithoutFormat())
    present(cmd, dst);
  else
    blit(cmd, dst);
}

void SceneRenderer::present(VkCommandBuffer cmd, const BlitDestination& dst) {
  gpu::Pass pass(device_, &timer_, cmd, "present");
  const gpu::ImageUse sampling{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                               VK_IMAGE_LAYOUT_GENERAL};
  gpu::transition(cmd, target_.handle(), kDrawing, sampling);
  gpu::transition(cmd, dst.image, dst.before, gpu::use::ComputeWrite);
  present_.bind(cmd);
  present_.push(
      cmd,
      gpu::Bindings().sampledImage(target_.view(), sampler_, VK_IMAGE_LAYOUT_GENERAL).storageImage(dst.storageView));
  present_.constants(cmd, uint32_t(dst.encodeSrgb ? 1 : 0));
  present_.dispatchOver(cmd, dst.extent, {8, 8});
  gpu::transition(cmd, dst.image, gpu::use::ComputeWrite, dst.after);
  gpu::transition(cmd, target_.handle(), sampling, gpu::use::TransferSrc);
}

void SceneRenderer::blit(VkCommandBuffer cmd, const BlitDestination& dst) {
  gpu::Pass pass(device_, &timer_, cmd, "present blit");
  gpu::transition(cmd, target_.handle(), kDrawing, gpu::use::TransferSrc);
  gpu::transition(cmd, dst.image, dst.before, gpu::use::TransferDst);
  const VkExtent2D src = target_.extent2d();
  VkImageBlit2 region{VK_STRUCTURE_TYPE_IMAGE_BLIT_2};
  region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = {static_cast<int32_t>(src.width), static_cast<int32_t>(src.height), 1};
  region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffsets[1] = {static_cast<int32_t>(dst.extent.width), static_cast<int32_t>(dst.extent.height), 1};
  VkBlitImageInfo2 info{VK_STRUCTURE_TYPE_BLIT_IMAGE_INFO_2};
  info.srcImage = target_.handle();
  info.srcImageLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  info.dstImage = dst.image;
  info.dstImageLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  info.regionCount = 1;
  info.pRegions = &region;
  const bool sameSize = src.width == dst.extent.width && src.height == dst.extent.height;
  info.filter = sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
  vkCmdBlitImage2(cmd, &info);
  gpu::transition(cmd, dst.image, gpu::use::TransferDst, dst.after);
}

}  // namespace vitrine::host
