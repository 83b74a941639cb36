#include "text/font.h"

#include "core/bounded_file.h"
#include "core/error.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_ADVANCES_H
#include FT_MODULE_H
#include FT_OUTLINE_H
#include FT_SIZES_H
#include <hb-ft.h>
#include <hb.h>

#include <fmt/format.h>

#include "text/freetype_errors.h"
#include <glm/common.hpp>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>

namespace vitrine::text {
namespace {

constexpr uintmax_t kMaxFontFileBytes = uintmax_t(64) << 20;  // the largest CJK fonts are ~20 MB

std::string describe(FT_Error error) { return freetypeError(int(error)); }

std::atomic<uint32_t> nextFontId{1};

// Glyphs are rasterised at this many times the atlas's pixels per em before their distance field is
// averaged down (FreeType's bitmap-to-SDF renderer is the more exact the finer its input).
constexpr uint32_t kSupersample = 2;

}  // namespace

struct Font::Impl {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  FT_Size shapeSize = nullptr;   // one pixel per font unit: shaping in exact font units
  FT_Size renderSize = nullptr;  // the atlas's pixels per em
  uint32_t renderPx = 0;
  uint32_t spreadPx = 0;
  hb_font_t* hb = nullptr;
  float unitsPerEm = 1.0f;
  std::filesystem::path path;
  std::string problem;
  bool fallback = false;
  uint32_t id = nextFontId.fetch_add(1);

  ~Impl() { close(); }

  void close() {
    if (hb) hb_font_destroy(hb);  // releases its reference to the face
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
    hb = nullptr;
    face = nullptr;
    library = nullptr;
    shapeSize = renderSize = nullptr;
    renderPx = spreadPx = 0;
  }

  // Empty when the file opens, has outlines and its first letter loads; otherwise why not.
  std::string open(const std::filesystem::path& file) {
    close();
    try {
      checkBoundedFile(file, kMaxFontFileBytes);
    } catch (const FileRefused& refused) {
      return refused.why == "it does not exist" ? "not found" : refused.why;
    }
    if (const FT_Error error = FT_Init_FreeType(&library)) return "FreeType did not start: " + describe(error);
    std::string why = openFace(file);
    if (!why.empty()) close();
    return why;
  }

  std::string openFace(const std::filesystem::path& file) {
    if (const FT_Error error = FT_New_Face(library, file.c_str(), 0, &face)) {
      face = nullptr;
      return describe(error);
    }
    if (!FT_IS_SCALABLE(face) || face->units_per_EM == 0) return "it holds no outlines to draw distance fields from";
    unitsPerEm = float(face->units_per_EM);
    FT_Error error = FT_New_Size(face, &shapeSize);
    if (!error) error = FT_New_Size(face, &renderSize);
    if (!error) error = FT_Activate_Size(shapeSize);
    if (!error) error = FT_Set_Char_Size(face, 0, FT_F26Dot6(face->units_per_EM) * 64, 72, 72);
    if (error) return describe(error);
    // A file cut short can still open: loading a glyph reads the tables rendering needs.
    FT_UInt probe = FT_Get_Char_Index(face, 'A');
    if (!probe) probe = FT_Get_Char_Index(face, 'a');
    error = FT_Load_Glyph(face, probe, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
    if (!error && face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return "its glyphs are not outlines";
    if (error) return describe(error);
    hb = hb_ft_font_create_referenced(face);
    hb_ft_font_set_load_flags(hb, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP);
    return {};
  }

  // Shaping measures at one pixel per font unit; the SDF size is selected only while rendering.
  struct RenderScope {
    Impl& impl;
    ~RenderScope() { FT_Activate_Size(impl.shapeSize); }
  };
};

Font::Font(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;
Font::~Font() = default;

Font Font::load(const std::filesystem::path& path, const std::filesystem::path& fallback) {
  auto impl = std::make_unique<Impl>();
  const std::string why = impl->open(path);
  if (why.empty()) {
    impl->path = path;
    return Font(std::move(impl));
  }
  impl->fallback = true;
  const std::string fallbackWhy = impl->open(fallback);
  if (fallbackWhy.empty()) {
    impl->path = fallback;
    impl->problem = fmt::format("{}: {}; using {} ({})", path.string(), why,
                                impl->face->family_name ? impl->face->family_name : "the fallback face",
                                fallback.string());
  } else {
    impl->problem = fmt::format("{}: {}; the fallback {} is unusable too ({}): no text is drawn", path.string(),
                                why, fallback.string(), fallbackWhy);
  }
  return Font(std::move(impl));
}

Font Font::fromAssets(const Assets& assets, const std::string& family) {
  if (const auto found = assets.font(family)) {
    Font font = load(*found);
    if (!font.problem().empty()) assets.reportMissing(font.problem());
    return font;
  }
  // Absent: Assets::missing() already names it and what stands in; say more only when nothing does.
  Font font = load(assets.root() / "fonts" / (family + ".woff2"));
  if (!font.usable()) assets.reportMissing(font.problem());
  return font;
}

bool Font::usable() const { return impl_ && impl_->face; }
bool Font::isFallback() const { return impl_ && impl_->fallback; }
const std::string& Font::problem() const {
  static const std::string none;
  return impl_ ? impl_->problem : none;
}
const std::filesystem::path& Font::path() const {
  static const std::filesystem::path none;
  return impl_ ? impl_->path : none;
}
uint32_t Font::id() const { return impl_ ? impl_->id : 0; }

std::string Font::name() const {
  if (!usable()) return "no font";
  const FT_Face face = impl_->face;
  std::string name = face->family_name ? face->family_name : "unnamed";
  if (face->style_name && std::strcmp(face->style_name, "Regular") != 0) name += std::string(" ") + face->style_name;
  return name;
}

float Font::ascender() const { return usable() ? float(impl_->face->ascender) / impl_->unitsPerEm : 0.0f; }
float Font::descender() const { return usable() ? -float(impl_->face->descender) / impl_->unitsPerEm : 0.0f; }

uint32_t Font::glyphFor(char32_t codepoint) const {
  return usable() ? FT_Get_Char_Index(impl_->face, FT_ULong(codepoint)) : 0;
}

float Font::plainAdvance(uint32_t glyph) const {
  if (!usable()) return 0.0f;
  FT_Fixed advance = 0;
  if (FT_Get_Advance(impl_->face, glyph, FT_LOAD_NO_SCALE, &advance)) return 0.0f;
  return float(advance) / impl_->unitsPerEm;
}

std::vector<ShapedGlyph> Font::shape(std::string_view utf8, const Shaping& shaping) const {
  std::vector<ShapedGlyph> glyphs;
  if (!usable() || utf8.empty() || utf8.size() > size_t(std::numeric_limits<int>::max())) return glyphs;
  hb_buffer_t* buffer = hb_buffer_create();
  hb_buffer_add_utf8(buffer, utf8.data(), int(utf8.size()), 0, int(utf8.size()));
  hb_buffer_guess_segment_properties(buffer);
  std::vector<hb_feature_t> features;
  if (shaping.trackingEm != 0.0f)
    for (const char* off : {"-liga", "-clig", "-dlig", "-hlig"}) {
      hb_feature_t feature;
      if (hb_feature_from_string(off, -1, &feature)) features.push_back(feature);
    }
  hb_shape(impl_->hb, buffer, features.data(), unsigned(features.size()));

  unsigned count = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buffer, &count);
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buffer, &count);
  const float toEm = 1.0f / (64.0f * impl_->unitsPerEm);  // 26.6 pixels at one pixel per font unit
  glyphs.reserve(count);
  glm::vec2 pen{0.0f};
  for (unsigned i = 0; i < count; ++i) {
    ShapedGlyph glyph;
    glyph.glyph = info[i].codepoint;
    glyph.cluster = info[i].cluster;
    glyph.pen = pen + glm::vec2(float(pos[i].x_offset), -float(pos[i].y_offset)) * toEm;  // y down
    glyph.advance = float(pos[i].x_advance) * toEm;
    // Tracking goes between clusters that advance, never after the last one or onto a mark.
    if (i + 1 < count && info[i + 1].cluster != info[i].cluster && pos[i].x_advance != 0)
      glyph.advance += shaping.trackingEm;
    pen += glm::vec2(glyph.advance, -float(pos[i].y_advance) * toEm);
    glyphs.push_back(glyph);
  }
  hb_buffer_destroy(buffer);
  return glyphs;
}

namespace {
constexpr float kMaxInkEm = 4.0f;
}  // namespace

GlyphSdf Font::renderSdf(uint32_t glyph, uint32_t pxPerEm, uint32_t spreadPx) const {
  GlyphSdf out;
  if (!usable() || pxPerEm == 0) return out;
  Impl& impl = *impl_;
  constexpr FT_Int32 kLoad = FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP;
  // The ink box in exact font units first.
  if (FT_Load_Glyph(impl.face, glyph, kLoad) || impl.face->glyph->format != FT_GLYPH_FORMAT_OUTLINE) return out;
  if (impl.face->glyph->outline.n_points == 0) return out;  // no ink: a space
  FT_BBox box;
  FT_Outline_Get_CBox(&impl.face->glyph->outline, &box);
  const float toEm = 1.0f / (64.0f * impl.unitsPerEm);
  out.inkMin = glm::vec2(float(box.xMin), -float(box.yMax)) * toEm;
  out.inkMax = glm::vec2(float(box.xMax), -float(box.yMin)) * toEm;
  // Letters fit in an em or two; a glyph whose ink spans more than kMaxInkEm is a broken (or hostile)
  // font, and rasterising it would take a bitmap, and a distance transform, of any size: no ink.
  if (glm::any(glm::greaterThan(out.inkMax - out.inkMin, glm::vec2(kMaxInkEm)))) return GlyphSdf{};

  // FreeType's outline SDF renderer mis-draws overlapping contours, which static instances of
  // variable fonts are full of (Fraunces, Cormorant): seams inside the letters, or with its "overlaps"
  // option whole counters cut out of a B. So the glyph is first rasterised by the ordinary renderer
  // (non-zero winding, supersampled where contours overlap) at twice the size, FT_RENDER_MODE_SDF
  // turns that bitmap into a distance field ("bsdf"), and 2x2 texels are averaged into one.
  const Impl::RenderScope scope{impl};
  const uint32_t px = pxPerEm * kSupersample, spread = spreadPx * kSupersample;
  if (FT_Activate_Size(impl.renderSize)) return out;
  if (impl.renderPx != px) {
    if (FT_Set_Pixel_Sizes(impl.face, 0, px)) return out;
    impl.renderPx = px;
  }
  if (impl.spreadPx != spread) {
    FT_Int value = FT_Int(spread);
    if (FT_Property_Set(impl.library, "bsdf", "spread", &value)) return out;
    impl.spreadPx = spread;
  }
  if (FT_Load_Glyph(impl.face, glyph, kLoad)) return out;
  impl.face->glyph->outline.flags |= FT_OUTLINE_OVERLAP;
  if (FT_Render_Glyph(impl.face->glyph, FT_RENDER_MODE_NORMAL)) return out;
  if (FT_Render_Glyph(impl.face->glyph, FT_RENDER_MODE_SDF)) return out;
  const FT_GlyphSlot slot = impl.face->glyph;
  const FT_Bitmap& bitmap = slot->bitmap;
  if (bitmap.pixel_mode != FT_PIXEL_MODE_GRAY || bitmap.width == 0 || bitmap.rows == 0) return out;

  // Fine texel (x, y) covers [L + x, L + x + 1) across and [T - y - 1, T - y) up; coarse texel (i, j)
  // covers fine columns k (left + i) .. k (left + i) + k - 1, and rows likewise from k top downwards.
  constexpr int k = int(kSupersample);
  const int L = slot->bitmap_left, T = slot->bitmap_top;
  const int W = int(bitmap.width), H = int(bitmap.rows);
  auto floorDiv = [](int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  const int left = floorDiv(L, k), top = -floorDiv(-T, k);
  const int right = -floorDiv(-(L + W), k), bottom = floorDiv(T - H, k);
  out.width = uint32_t(right - left);
  out.height = uint32_t(top - bottom);
  out.texels.resize(size_t(out.width) * out.height);
  auto fine = [&](int x, int y) -> int {  // outside the bitmap is beyond the spread: 0
    if (x < 0 || y < 0 || x >= W || y >= H) return 0;
    const int row = bitmap.pitch >= 0 ? y : H - 1 - y;
    return bitmap.buffer[ptrdiff_t(row) * std::abs(bitmap.pitch) + x];
  };
  for (uint32_t j = 0; j < out.height; ++j)
    for (uint32_t i = 0; i < out.width; ++i) {
      const int x0 = k * (left + int(i)) - L, y0 = T - k * (top - int(j));
      int sum = 0;
      for (int dy = 0; dy < k; ++dy)
        for (int dx = 0; dx < k; ++dx) sum += fine(x0 + dx, y0 + dy);
      out.texels[size_t(j) * out.width + i] = uint8_t((sum + k * k / 2) / (k * k));
    }
  const float coarse = float(pxPerEm);
  out.offset = glm::vec2(float(left), -float(top)) / coarse;
  out.size = glm::vec2(float(out.width), float(out.height)) / coarse;
  return out;
}

// --- The atlas.

GlyphAtlas::GlyphAtlas(const AtlasOptions& options)
    : options_(options), texels_(size_t(options.width) * options.height, 0) {
  if (options.width == 0 || options.height == 0 || options.pxPerEm == 0 || options.spreadPx < 1 ||
      options.spreadPx > 16)
    throw Error(fmt::format("A text atlas needs a size, pixels per em and a spread of 1 to 16 pixels, not {}x{} at {} "
                            "px with {} px",
                            options.width, options.height, options.pxPerEm, options.spreadPx));
}

const AtlasGlyph* GlyphAtlas::find(const Font& font, uint32_t glyph) const {
  const auto it = glyphs_.find((uint64_t(font.id()) << 32) | glyph);
  return it == glyphs_.end() ? nullptr : &it->second;
}

bool GlyphAtlas::place(uint32_t width, uint32_t height, uint32_t& x, uint32_t& y) {
  const uint32_t w = width + options_.gutterPx, h = height + options_.gutterPx;
  Shelf* best = nullptr;
  for (Shelf& shelf : shelves_)  // the lowest shelf it fits on wastes least
    if (shelf.height >= h && shelf.x + w <= options_.width && (!best || shelf.height < best->height)) best = &shelf;
  if (!best) {
    const uint32_t top = shelves_.empty() ? 0 : shelves_.back().y + shelves_.back().height;
    if (w > options_.width || top + h > options_.height) return false;
    shelves_.push_back({top, h, 0});
    best = &shelves_.back();
  }
  x = best->x;
  y = best->y;
  best->x += w;
  return true;
}

const AtlasGlyph& GlyphAtlas::glyph(const Font& font, uint32_t index) {
  const uint64_t key = (uint64_t(font.id()) << 32) | index;
  if (const auto it = glyphs_.find(key); it != glyphs_.end()) return it->second;
  const GlyphSdf sdf = font.renderSdf(index, options_.pxPerEm, options_.spreadPx);
  AtlasGlyph placed;
  placed.inkMin = sdf.inkMin;
  placed.inkMax = sdf.inkMax;
  if (sdf.width > 0) {
    if (!place(sdf.width, sdf.height, placed.x, placed.y))
      throw Error(fmt::format("The {}x{} text atlas is full: glyph {} of {} ({}x{} texels) does not fit after {} "
                              "glyphs; give the text pass a larger atlas",
                              options_.width, options_.height, index, font.name(), sdf.width, sdf.height,
                              glyphs_.size()));
    placed.width = sdf.width;
    placed.height = sdf.height;
    placed.offset = sdf.offset;
    placed.size = sdf.size;
    for (uint32_t row = 0; row < sdf.height; ++row)
      std::memcpy(&texels_[size_t(placed.y + row) * options_.width + placed.x], &sdf.texels[size_t(row) * sdf.width],
                  sdf.width);
    ++revision_;
  }
  return glyphs_.emplace(key, placed).first->second;
}

TextLayout GlyphAtlas::layout(const Font& font, std::string_view utf8, const Shaping& shaping) {
  TextLayout layout;
  layout.reachEm = reachEm();
  const glm::vec2 texel = 1.0f / glm::vec2(float(options_.width), float(options_.height));
  bool anyInk = false;
  for (const ShapedGlyph& shaped : font.shape(utf8, shaping)) {
    layout.advance = shaped.pen.x + shaped.advance;
    const AtlasGlyph& placed = glyph(font, shaped.glyph);
    if (placed.width == 0) continue;
    GlyphQuad quad;
    quad.min = shaped.pen + placed.offset;
    quad.max = quad.min + placed.size;
    quad.uvMin = glm::vec2(float(placed.x), float(placed.y)) * texel;
    quad.uvMax = glm::vec2(float(placed.x + placed.width), float(placed.y + placed.height)) * texel;
    quad.cluster = shaped.cluster;
    layout.quads.push_back(quad);
    const glm::vec2 inkMin = shaped.pen + placed.inkMin, inkMax = shaped.pen + placed.inkMax;
    layout.inkMin = anyInk ? glm::min(layout.inkMin, inkMin) : inkMin;
    layout.inkMax = anyInk ? glm::max(layout.inkMax, inkMax) : inkMax;
    anyInk = true;
  }
  return layout;
}

float GlyphAtlas::sampleLinear(glm::vec2 uv) const {
  const glm::vec2 at = uv * glm::vec2(float(width()), float(height())) - 0.5f;
  const glm::vec2 base = glm::floor(at), f = at - base;
  auto texel = [&](int x, int y) {
    x = std::clamp(x, 0, int(width()) - 1);
    y = std::clamp(y, 0, int(height()) - 1);
    return float(texels()[size_t(y) * width() + size_t(x)]) / 255.0f;
  };
  const int x = int(base.x), y = int(base.y);
  const float top = texel(x, y) * (1 - f.x) + texel(x + 1, y) * f.x;
  const float bottom = texel(x, y + 1) * (1 - f.x) + texel(x + 1, y + 1) * f.x;
  return top * (1 - f.y) + bottom * f.y;
}

}  // namespace vitrine::text
