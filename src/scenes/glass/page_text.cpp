#include "scenes/glass/page_text.h"

#include <string>

namespace vitrine::glass {
namespace {

constexpr float kTitleTrackingEm = 0.04f;  // the small-caps title's letter-spacing

text::Shaping shaping(bool title) { return title ? text::Shaping{kTitleTrackingEm} : text::Shaping{}; }

}  // namespace

PageText::PageText(const SceneContext& context)
    : bodyFont_(text::Font::fromAssets(context.assets, "Fraunces")),
      titleFont_(text::Font::fromAssets(context.assets, "CormorantSC")),
      text_(context,
            {{&bodyFont_, pageParagraphs(), shaping(false)}, {&titleFont_, {pageParagraphs().front()}, shaping(true)}},
            text::AtlasOptions{1024, 1024, 48, 8, 1}) {
  const auto measure = [&](const std::string& candidate, bool title) {
    return text_.layout(title ? titleFont_ : bodyFont_, candidate, shaping(title)).advance;
  };
  for (const PageLine& line : wrapPage(pageParagraphs(), measure)) {
    lines_.push_back(line);
    layouts_.push_back(text_.layout(line.title ? titleFont_ : bodyFont_, line.text, shaping(line.title)));
  }
}

void PageText::record(const FrameContext& frame, gpu::Image& target, float em, float left) {
  std::vector<text::TextDraw> draws;
  const float top = 2.5f * em;
  for (size_t i = 0; i < lines_.size(); ++i) {
    const PageLine& line = lines_[i];
    text::TextDraw draw;
    draw.layout = &layouts_[i];
    draw.anchor = text::Anchor::Baseline;
    draw.sizePx = em * (line.title ? kPageTitleScale : 1.0f);
    draw.position = {left, top + line.baselineEm * em};
    draw.color = line.title ? glm::vec4(0.35f, 0.08f, 0.05f, 1.0f) : glm::vec4(0.02f, 0.02f, 0.025f, 1.0f);
    draws.push_back(draw);
  }
  text_.record(frame, target, draws);
}

}  // namespace vitrine::glass
