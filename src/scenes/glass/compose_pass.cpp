#include "scenes/glass/compose_pass.h"

#include "scenes/glass/sample_pass.h"
#include "scenes/glass/world_view.h"
#include "shaders/glass/pass_push.h"

#include <algorithm>

namespace vitrine::glass {
namespace {

constexpr float kPageBodyEm = 19.0f;  // body text size, world units: the page scales with the view's height

}  // namespace

ComposePass::ComposePass(const SceneContext& context)
    : program_(context.programs, "glass/compose.comp"), page_(context) {}

void ComposePass::record(const FrameContext& frame, gpu::Image& backdrop, gpu::Image& photo, BackdropKind kind,
                         glm::vec2 photoSize, VkExtent2D extent) {
  const glm::vec2 view{float(extent.width), float(extent.height)};
  const bool hasPhoto = photoSize.x > 0.0f && kind != BackdropKind::Gradient && kind != BackdropKind::Checker;
  // Cover the view with the photo, as CSS' background-size: cover does.
  const float cover = hasPhoto ? std::max(view.x / photoSize.x, view.y / photoSize.y) : 1.0f;
  const glm::vec2 scale = hasPhoto ? view / (photoSize * cover) : glm::vec2(1.0f);
  const bool page = kind == BackdropKind::Page;
  const float em = kPageBodyEm * view.y / kViewHeight;  // body em in pixels
  const float columnPx = kPageColumnEm * em;
  const int source = kind == BackdropKind::Checker ? GLASS_SOURCE_CHECKER
                     : hasPhoto                    ? GLASS_SOURCE_PHOTO
                                                   : GLASS_SOURCE_GRADIENT;
  const shader::GlassComposePush push{
      .photoScale = scale,
      .source = source,
      .paper = page ? 1u : 0u,
      .paperLeft = 0.5f * (view.x - columnPx) - 1.5f * em,  // the column with 1.5 em of margin each side
      .paperRight = 0.5f * (view.x + columnPx) + 1.5f * em};
  sampleInto(frame, program_, {"photo", "backdrop"}, photo, backdrop, backdrop.mipView(0), extent, push);
  if (page) page_.record(frame, backdrop, em, 0.5f * (view.x - columnPx));
  gpu::generateMips(frame.cmd, backdrop, gpu::use::FragmentSample);
}

}  // namespace vitrine::glass
