#include "scenes/neon/look_passes.h"

#include "maths/color.h"
#include "scenes/neon/look.h"
#include "shaders/neon/bloom_push.h"
#include "shaders/neon/composite_push.h"
#include "shaders/neon/dof_push.h"

namespace vitrine::neon {
namespace {

constexpr VkFormat kHdr = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkImageLayout kGeneral = VK_IMAGE_LAYOUT_GENERAL;
constexpr VkImageLayout kSampled = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

gpu::ImageDecl chainDecl(std::string name) {
  // Level L of the chain is the target's size >> L; mip L - 1 of a half-size image holds it.
  return {std::move(name), kHdr, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT, gpu::ImageSize::relative(0.5f),
          0};
}

}  // namespace

LookPasses::LookPasses(const SceneContext& context)
    : device_(context.device),
      resources_(context.resources),
      down_(context.programs, "neon/bloom_down.comp"),
      up_(context.programs, "neon/bloom_up.comp"),
      dof_(context.programs, "neon/dof.comp"),
      composite_(context.programs, "neon/composite.comp") {
  downChain_ = resources_.declare(chainDecl("neon bloom down"));
  upChain_ = resources_.declare(chainDecl("neon bloom up"));
  focused_ = resources_.declare({"neon depth of field", kHdr, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
                                 gpu::ImageSize::relative(1.0f)});
}

// The chain described in look.h: down from the glow to level N, then up from N to 1, each step a
// separate dispatch behind a barrier, no dispatch sampling the mip it writes.
gpu::Image& LookPasses::bloom(const FrameContext& frame, const Settings& settings, gpu::Image& glow) {
  const auto pass = frame.pass("neon bloom");
  gpu::Image& down = frame.image(downChain_);
  gpu::Image& up = frame.image(upChain_);
  const VkSampler mipped = device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp, true);
  const VkExtent2D size = down.extent2d();
  const int levels = std::min(bloomLevels(size.height * 2), int(down.desc().mips));
  const auto dispatch = [&](const gpu::ComputeProgram& program, int mip) {
    program.dispatchOver(frame.cmd, VkExtent2D{std::max(1u, size.width >> mip), std::max(1u, size.height >> mip)});
  };

  frame.transition(glow, gpu::use::ComputeSample);
  frame.transition(down, gpu::use::ComputeSampleWrite);
  down_.bind(frame.cmd);
  for (int level = 1; level <= levels; ++level) {
    const bool first = level == 1;
    if (!first) frame.transition(down, gpu::use::ComputeSampleWrite);  // level - 1 was just written
    const shader::NeonBloomDownPush push{first ? 0.0f : float(level - 2), kBloomThreshold, kBloomKnee, first ? 1u : 0u};
    down_.constants(frame.cmd, push);
    down_.push(frame.cmd,
               gpu::Bindings()
                   .sampledImage("source", first ? glow.view() : down.view(), mipped, first ? kSampled : kGeneral)
                   .storageImage("target", down.mipView(uint32_t(level - 1))));
    dispatch(down_, level - 1);
  }
  frame.transition(down, gpu::use::ComputeSampleWrite);
  frame.transition(up, gpu::use::ComputeSampleWrite);
  up_.bind(frame.cmd);
  for (int level = levels - 1; level >= 1; --level) {
    if (level < levels - 1) frame.transition(up, gpu::use::ComputeSampleWrite);
    const bool fromDown = level == levels - 1;  // the smallest level comes from the down chain
    const shader::NeonBloomUpPush push{float(level), float(level - 1), settings.bloomRadius, 1.0f};
    up_.constants(frame.cmd, push);
    up_.push(frame.cmd, gpu::Bindings()
                            .sampledImage("smaller", fromDown ? down.view() : up.view(), mipped, kGeneral)
                            .sampledImage("current", down.view(), mipped, kGeneral)
                            .storageImage("target", up.mipView(uint32_t(level - 1))));
    dispatch(up_, level - 1);
  }
  return levels > 1 ? up : down;  // level 1
}

void LookPasses::record(const FrameContext& frame, const Settings& settings, const LookInputs& in) {
  const bool bloomOn = settings.stage >= Stage::Bloom;
  const bool dofOn = settings.stage >= Stage::Dof;
  const VkExtent2D extent = in.scene.extent2d();
  const VkSampler linear = device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp);
  gpu::Image* bloomed = &frame.image(upChain_);  // not read unless the bloom ran
  if (bloomOn) bloomed = &bloom(frame, settings, in.glow);
  gpu::Image& focused = frame.image(focused_);
  if (dofOn) {
    const auto pass = frame.pass("neon dof");
    frame.transition(in.scene, gpu::use::ComputeSample);
    frame.transition(in.depth, gpu::use::ComputeSample);
    frame.transition(focused, gpu::use::ComputeWrite);
    const float pixels = float(extent.height) / 1080.0f;  // circles of confusion scale with the frame
    const shader::NeonDofPush push{glm::vec2(extent.width, extent.height), in.near, settings.focalDistance,
                                   settings.aperture * 6.0f * pixels, 14.0f * pixels, in.dofTaps, 0.0f};
    dof_.bind(frame.cmd);
    dof_.constants(frame.cmd, push);
    dof_.push(frame.cmd, gpu::Bindings()
                             .sampledImage("colour", in.scene.view(), linear, kSampled)
                             .sampledImage("depth", in.depth.view(),
                                           device_.sampler(gpu::Device::Filter::Nearest, gpu::Device::Address::Clamp),
                                           kSampled)
                             .storageImage("target", focused.view()));
    dof_.dispatchOver(frame.cmd, extent);
  }
  const auto pass = frame.pass("neon composite");
  gpu::Image& scene = dofOn ? focused : in.scene;
  frame.transition(scene, gpu::use::ComputeSample);
  frame.transition(*bloomed, gpu::use::ComputeSample);
  frame.transition(frame.target, gpu::use::ComputeWrite);
  uint32_t flags = 0;
  switch (settings.stage) {
    case Stage::Base:
    case Stage::Tubes: flags = 0; break;
    case Stage::Bloom:
    case Stage::Dof: flags = shader::NEON_COMPOSITE_BLOOM; break;
    case Stage::Tint: flags = shader::NEON_COMPOSITE_BLOOM | shader::NEON_COMPOSITE_TINT; break;
    case Stage::Final: flags = shader::NEON_COMPOSITE_ALL; break;
  }
  shader::NeonCompositePush push{};
  push.tintColour0 = maths::srgbToLinear(settings.tintA);
  push.tintStrength = settings.tintStrength;
  push.tintColour1 = maths::srgbToLinear(settings.tintB);
  push.time = in.time;
  push.bloomStrength = settings.bloomStrength * 0.4f;  // the up chain sums every level; thin tubes need more
  push.bloomLod = 0.0f;
  push.vignette = settings.vignette;
  push.grain = settings.grain;
  push.aberration = settings.aberration / (0.7f * float(extent.width));  // pixels at the corners -> uv per unit
  push.horizonY = in.mirrorRow;
  push.mirrorStrength = settings.mirror;
  push.mirrorDistortion = settings.distortion * 40.0f * float(extent.height) / 1080.0f;
  push.mirrorFade = 0.35f * float(extent.height);
  push.frame = uint32_t(in.time * 60.0f);
  push.flags = flags;
  composite_.bind(frame.cmd);
  composite_.constants(frame.cmd, push);
  composite_.push(frame.cmd, gpu::Bindings()
                                 .sampledImage("scene", scene.view(), linear, kSampled)
                                 .sampledImage("bloom", bloomed->view(),
                                               device_.sampler(gpu::Device::Filter::Linear,
                                                               gpu::Device::Address::Clamp, true),
                                               kSampled)
                                 .storageImage("target", frame.target.view()));
  composite_.dispatchOver(frame.cmd, extent);
}

}  // namespace vitrine::neon
