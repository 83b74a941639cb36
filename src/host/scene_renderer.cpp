#include "host/scene_renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "gpu/check.h"
#include "gpu/fault_injection.h"
#include <glm/matrix.hpp>
#include "shaders/host/output_warp.h"
#include "shaders/host/present_push.h"

namespace vitrine::host {

namespace {
// present.comp with or without the warp (its specialisation constant 0).
gpu::ComputeProgram presentVariant(gpu::ProgramLibrary& programs, bool warped) {
  return gpu::ComputeProgram(programs, "host/present.comp", {.specialization = {warped ? 1 : 0}});
}
}  // namespace

SceneRenderer::SceneRenderer(const gpu::Device& device, gpu::ProgramLibrary& programs, const Assets& assets,
                             uint32_t framesInFlight)
    : device_(device),
      programs_(programs),
      assets_(assets),
      framesInFlight_(framesInFlight),
      timer_(device, framesInFlight),
      stream_(device),
      presents_{presentVariant(programs, false), presentVariant(programs, true)} {}

// Shutdown is the one place that waits: every retired scene and pipeline must be gone before the
// program library they registered with.
SceneRenderer::~SceneRenderer() {
  filters_.reset();  // retires its filters
  device_.drainRetired();
}

FilterChain& SceneRenderer::filters() {
  if (!filters_) filters_ = std::make_unique<FilterChain>(device_, programs_);
  return *filters_;
}

void SceneRenderer::clear() {
  // Frames in flight may still use the old scene's pipelines, buffers and images: retire, don't wait.
  if (scene_) device_.retire(std::move(scene_));
  if (resources_) device_.retire(std::move(resources_));
  if (target_) device_.retire(std::move(target_));
  info_ = nullptr;
}

void SceneRenderer::setScene(const SceneInfo& info, SceneFactory create) {
  clear();
  if (!create) throw Error(fmt::format("scene {} has no factory (cmake/Scenes.cmake lists the scenes)", info.name));
  if (gpu::injectedSceneFailure(info.name))
    throw Error(fmt::format("scene {} failed to start (injected by VITRINE_INJECT)", info.name));
  resources_ = std::make_unique<gpu::FrameResources>(device_);
  resources_->setFramesInFlight(framesInFlight_);  // before the scene declares per-frame buffers
  sceneExtent_ = {0, 0};  // the new scene's images are sized at its first frame
  scene_ = create(SceneContext{{device_, programs_, *resources_}, assets_, SceneEvents(events_, info.name), *audio_,
                               framesInFlight_, realtime_});
  info_ = &info;
}

std::string SceneRenderer::applyParameters(const params::KeyValues& values) {
  const Scene& scene = *scene_;
  return params::applyValues(scene_->parameters(), values, [&scene] { return scene.checkParameters(); });
}

double SceneRenderer::costRatio(const params::KeyValues& change) {
  const params::Bound current = scene_->parameters();
  const auto scratch = current.schema->makeDefaults();
  for (const params::Param& param : current.schema->params()) param.copy(scratch.get(), current.settings);
  if (!params::applyValues({current.schema, scratch.get()}, change).empty()) return 1.0;
  const double now = scene_->frameCost(current.settings);
  return now > 0.0 ? scene_->frameCost(scratch.get()) / now : 1.0;
}

std::string SceneRenderer::applyPreset(std::string_view name) {
  const Scene& scene = *scene_;
  return params::applyPreset(scene_->parameters(), name, [&scene] { return scene.checkParameters(); });
}

namespace {

shader::HostOutputWarp warpBlock(const maths::OutputWarp& warp) {
  const maths::WarpMatrices m = maths::warpMatrices(warp);
  const glm::mat3 rows = glm::transpose(m.unpin);
  const maths::EdgeBlend& b = warp.blend;
  return {glm::vec4(rows[0], 0.0f), glm::vec4(rows[1], 0.0f), glm::vec4(rows[2], 0.0f), glm::vec4(m.sourceU, 0.0f),
          glm::vec4(m.sourceV, 0.0f), {b.left, b.top, b.right, b.bottom}, {b.curve, b.gamma, 0.0f, 0.0f}};
}

}  // namespace

VkExtent2D frameExtent(VkExtent2D output, const maths::OutputWarp* warp) {
  if (!warp) return output;
  const bool turned = warp->quarterTurns % 2 != 0;
  const float width = float(turned ? output.height : output.width), height = float(turned ? output.width : output.height);
  const glm::vec4& r = warp->region;
  return {std::max(1u, uint32_t(std::lround(width / (r.z - r.x)))), std::max(1u, uint32_t(std::lround(height / (r.w - r.y))))};
}

void checkWarpedFrame(const gpu::Device& device, VkExtent2D output, const maths::OutputWarp& warp, std::string_view where) {
  // In doubles: a region of 1e-30 makes a side no integer holds.
  const bool turned = warp.quarterTurns % 2 != 0;
  const double width = turned ? output.height : output.width, height = turned ? output.width : output.height;
  const double across = double(warp.region.z) - warp.region.x, down = double(warp.region.w) - warp.region.y;
  const double frameWidth = std::round(width / across), frameHeight = std::round(height / down);
  const uint32_t limit = device.limits().maxImageDimension2D;
  if (frameWidth <= limit && frameHeight <= limit) return;
  throw Error(fmt::format("{}: a region of {:.3g} x {:.3g} of a {}x{} output needs a {:.0f}x{:.0f} frame, outside what {} "
                          "supports (1 to {} per side): widen the region.",
                          where, across, down, output.width, output.height, frameWidth, frameHeight,
                          device.properties().deviceName, limit));
}

void SceneRenderer::ensureTarget(VkExtent2D output) {
  const float scale = std::clamp(scene_->renderScale(), 0.1f, 1.0f);
  const VkExtent2D wanted{std::max(1u, static_cast<uint32_t>(std::lround(output.width * scale))),
                          std::max(1u, static_cast<uint32_t>(std::lround(output.height * scale)))};
  if (!target_ || target_.extent2d().width != wanted.width || target_.extent2d().height != wanted.height) {
    if (target_) device_.retire(std::move(target_));  // the frame in flight may still read it
    gpu::ImageDesc desc;
    desc.extent = {wanted.width, wanted.height, 1};
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                 VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    target_ = gpu::Image(device_, desc, "HDR target");
  }
  if (wanted.width == sceneExtent_.width && wanted.height == sceneExtent_.height) return;
  sceneExtent_ = wanted;
  resources_->resize(wanted);
  scene_->resize(wanted);
}

void SceneRenderer::recordTarget(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, VkExtent2D output) {
  device_.collectRetired();
  ensureTarget(output);
  timer_.beginFrame(cmd, slot);
  resources_->beginFrame(cmd, stream_, slot);
  target_.discard();  // a scene draws every texel each frame
  scene_->record(FrameContext{device_, cmd, &timer_, target_, *resources_, stream_, input, slot, drawing_});
  if (hasFilters() && drawing_) filters_->record(cmd, slot, &timer_, stream_, target_, input, drawing_, realtime_);
}

void SceneRenderer::record(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, const BlitDestination& dst,
                           const Crossfade& fade) {
  recordTarget(cmd, slot, input, frameExtent(dst.extent, dst.warp));
  // A transition draws both frames into the target, where the guard and every output find it.
  transitioned_ = fade.transition && fade.other && drawing_;
  if (transitioned_)
    fade.transition->record(cmd, slot, &timer_, stream_, target_, *fade.other, fade.weight, input, realtime_);
  const Crossfade mix = transitioned_ ? Crossfade{} : fade;
  shown_ = guard_ && drawing_ && canPresent(dst) ? &guardFrame(cmd, mix, input.time) : nullptr;
  recordOutput(cmd, dst, mix);
}

void SceneRenderer::recordOutput(VkCommandBuffer cmd, const BlitDestination& dst, const Crossfade& fade) {
  if (!canPresent(dst))
    blit(cmd, dst);
  else if (shown_)  // the guard's frame, the fade already in it
    present(cmd, dst, *shown_, {});
  else
    present(cmd, dst, target_, transitioned_ ? Crossfade{} : fade);
}

void SceneRenderer::recordScaled(VkCommandBuffer cmd, gpu::Image& output) {
  output.discard();  // every texel is written
  const BlitDestination dst{output.handle(), output.extent2d(), output.lastUse(), gpu::use::TransferSrc, output.view()};
  if (canPresent(dst))
    present(cmd, dst, target_, {});
  else
    blit(cmd, dst);
  output.assumeUse(gpu::use::TransferSrc);
}

bool SceneRenderer::canPresent(const BlitDestination& dst) const {
  return dst.storageView && device_.storageWriteWithoutFormat();
}

// The frame at the target's size with the incoming scene mixed in and the flashes held back: what every
// output of this frame shows, so one guard covers them all whatever their warps.
gpu::Image& SceneRenderer::guardFrame(VkCommandBuffer cmd, const Crossfade& fade, double time) {
  gpu::Pass pass(device_, &timer_, cmd, "flash guard");
  target_.use(cmd, gpu::use::ComputeSample);
  gpu::Image& other = fade.other ? *fade.other : target_;
  if (fade.other) other.use(cmd, gpu::use::ComputeSample);
  return guard_->guard(cmd, GuardSources{target_.view(), other.view(), fade.other ? std::clamp(fade.weight, 0.0f, 1.0f) : 0.0f},
                       target_.extent2d(), time);
}

void SceneRenderer::present(VkCommandBuffer cmd, const BlitDestination& dst, gpu::Image& frame, const Crossfade& fade) {
  gpu::Pass pass(device_, &timer_, cmd, dst.pass);
  frame.use(cmd, gpu::use::ComputeSample);
  gpu::Image& other = fade.other ? *fade.other : frame;
  if (fade.other) other.use(cmd, gpu::use::ComputeSample);
  gpu::transition(cmd, dst.image, dst.before, gpu::use::ComputeWrite);
  const VkSampler linear = device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp);
  const bool warped = dst.warp && !dst.warp->isIdentity();
  const gpu::StreamSlice warp = stream_.writeValue(warpBlock(warped ? *dst.warp : maths::OutputWarp{}));
  const gpu::ComputeProgram& program = presents_[warped ? 1 : 0];
  program.bind(cmd);
  program.push(cmd, gpu::Bindings()
                        .sampledImage("source", frame.view(), linear, gpu::use::ComputeSample.layout)
                        .storageImage("destination", dst.storageView)
                        .sampledImage("incoming", other.view(), linear, gpu::use::ComputeSample.layout)
                        .uniformBuffer("Warp", warp.buffer, warp.offset, sizeof(shader::HostOutputWarp)));
  program.constants(cmd, shader::HostPresentPush{.encodeSrgb = dst.encodeSrgb ? 1u : 0u,
                                                 .fade = fade.other ? std::clamp(fade.weight, 0.0f, 1.0f) : 0.0f});
  program.dispatchOver(cmd, dst.extent);
  gpu::transition(cmd, dst.image, gpu::use::ComputeWrite, dst.after);
}

void SceneRenderer::blit(VkCommandBuffer cmd, const BlitDestination& dst) {
  gpu::Pass pass(device_, &timer_, cmd, "present blit");
  target_.use(cmd, gpu::use::TransferSrc);
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
