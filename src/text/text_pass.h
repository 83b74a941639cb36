#pragma once
// Type drawn by a scene in its own compute pass over frame.target, from the distance-field atlas of
// text/font.h. A scene owns a TextPass: created with the fonts and strings it will draw (their glyphs
// go into the atlas, an image declared with its texels as initial data), it lays strings out and
// records any number of draws a frame.
//
//   TextPass text(context, {{&cormorant_, {"AMBER", "ROSE", "CRIMSON"}, {0.08f}}, {&italic_, {"CHROMA"}}});
//   amber_ = text.layout(cormorant_, "AMBER", {0.08f});          // already in the atlas
//   ...
//   text.record(frame, {{&amber_, {0.5f, 0.3f}, true, 64.0f, {1.0f, 0.6f, 0.2f, 1.0f}, 1.0f, typed}});
//
// Only the pixels near the text are touched: the draws' boxes are cut into 16x16 tiles and one
// dispatch runs over those tiles, each pixel blending every draw that covers it in order (a full-screen
// pass would cost far more, fragment work most of all on a compute-heavy GPU). Edges are anti-aliased
// from the distance field over a width fixed in target pixels, from the known pixels per em, so text
// is equally crisp at every size. The target is read and written as a storage image (rgba16f); pixels
// no draw reaches are not written at all.
#include "frame/frame_context.h"
#include "text/font.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <vector>

namespace vitrine::text {

// Strings a scene will draw in one font, laid out with one shaping, so their glyphs are in the atlas
// from the start.
struct TextSource {
  const Font* font = nullptr;
  std::vector<std::string> strings;
  Shaping shaping;
};

enum class Anchor {
  InkCentre,  // `position` is the centre of the layout's ink box (a type-in does not shift it)
  Baseline,   // `position` is the layout's origin: the start of the line, on the baseline
};

// A soft halo around the letters, from the same distance field: additive light, so an HDR colour
// feeds a bloom pass. It reaches at most as far as the atlas's spread (TextLayout::reachEm).
struct Glow {
  glm::vec3 color{0.0f};  // linear; strength is its brightness
  float radiusEm = 0.0f;  // 0: no glow; clamped to the distance field's reach
};

struct TextDraw {
  const TextLayout* layout = nullptr;  // must stay alive until record() returns
  glm::vec2 position{0.0f};            // target pixels from the top-left, or 0..1 when `normalized`
  bool normalized = false;
  float sizePx = 32.0f;                // the em in target pixels
  // Linear RGB and alpha, straight (not premultiplied): the text covers the target by alpha times
  // opacity times coverage.
  glm::vec4 color{1.0f};
  float opacity = 1.0f;  // scales the fill and the glow: fades
  // Type-in: the fraction of the layout's glyphs shown, in reading order; the glyph at the front
  // fades in over its share, so progress from 0 to 1 types the word.
  float reveal = 1.0f;
  Glow glow;
  float softnessEm = 0.0f;  // widens the anti-aliased edge: letters that come into focus
  Anchor anchor = Anchor::InkCentre;
};

// The pixels a draw may change, [x0, x1) x [y0, y1), clipped to the target; empty when x0 >= x1.
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

class TextPass {
 public:
  static constexpr uint32_t kTile = 16;  // pixels on a side of a tile, the work of one workgroup

  // Rasterises every source string's glyphs and declares the atlas image with them as initial data.
  TextPass(const GpuContext& context, const std::vector<TextSource>& sources, const AtlasOptions& options = {});

  // A layout drawn from this pass's atlas. Glyphs not yet in it are added and uploaded at the next
  // record(); better to name every string at construction.
  TextLayout layout(const Font& font, std::string_view utf8, const Shaping& shaping = {});

  // Blends the draws, in order, over frame.target. Draws without a layout, with nothing revealed or
  // fully transparent are skipped.
  void record(const FrameContext& frame, const std::vector<TextDraw>& draws) { record(frame, frame.target, draws); }
  // The same over another rgba16f image with storage usage (a scene's own HDR image, before its bloom).
  void record(const FrameContext& frame, gpu::Image& target, const std::vector<TextDraw>& draws);

  const GlyphAtlas& atlas() const { return atlas_; }
  // The pixels `draw` may change in a target of `extent`: the ink box widened by the glow or edge.
  static PixelBox bounds(const TextDraw& draw, VkExtent2D extent);

 private:
  const gpu::Device& device_;
  gpu::ComputeProgram program_;
  GlyphAtlas atlas_;
  gpu::ImageHandle image_;
  uint64_t uploaded_ = 0;  // the atlas revision the image holds
};

}  // namespace vitrine::text
