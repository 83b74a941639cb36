#include "scenes/glass/compose_pass.h"

#include "scenes/glass/sample_pass.h"
#include "scenes/glass/world_view.h"

#include <algorithm>

namespace vitrine::glass {
namespace {

constexpr float kPageBodyEm = 19.0f;  // body text size, world units: the page scales with the view's height

struct ComposePush {
  glm::vec4 photo;  // photo aspect / view aspect cover scale xy, has photo, page panel
  glm::ivec4 kind;  // 0 gradient, 1 checker, 2 photo; panel on
  glm::vec4 panel;  // the page's paper, in pixels: x0, y0, x1, y1
};

}  // namespace

ComposePass::ComposePass(const SceneContext& context)
    : program_(context.programs, "glass/compose.comp",
               {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(ComposePush)}),
      page_(context) {}

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
  const glm::vec4 panel{0.5f * (view.x - columnPx) - 1.5f * em, 0.0f, 0.5f * (view.x + columnPx) + 1.5f * em, view.y};
  const int source = kind == BackdropKind::Checker ? 1 : hasPhoto ? 2 : 0;
  const ComposePush push{{scale, hasPhoto ? 1.0f : 0.0f, 0.0f}, {source, page ? 1 : 0, 0, 0}, panel};
  sampleInto(frame, program_, photo, backdrop, backdrop.mipView(0), extent, push);
  if (page) page_.record(frame, backdrop, em, 0.5f * (view.x - columnPx));
  gpu::generateMips(frame.cmd, backdrop, gpu::use::FragmentSample);
}

}  // namespace vitrine::glass
