#pragma once
// The page's words set with the text module: its two fonts, their glyphs rasterised once into the
// atlas, and the page wrapped to its column (page.h) with every line's layout, so that drawing the
// page shapes nothing. The compose pass draws it over the paper whenever the backdrop is made again.
#include "scenes/glass/page.h"
#include "scenes/scene.h"
#include "text/text_pass.h"

#include <vector>

namespace vitrine::glass {

class PageText {
 public:
  explicit PageText(const SceneContext& context);
  // Sets the page over `target` with the body em `em` pixels and the column's left edge at `left` pixels.
  void record(const FrameContext& frame, gpu::Image& target, float em, float left);

 private:
  text::Font bodyFont_, titleFont_;
  text::TextPass text_;
  std::vector<PageLine> lines_;
  std::vector<text::TextLayout> layouts_;  // one a line
};

}  // namespace vitrine::glass
