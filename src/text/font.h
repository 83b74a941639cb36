#pragma once
// Type on the CPU, no Vulkan: a face loaded with FreeType, strings shaped with HarfBuzz, and glyphs
// rasterised as signed distance fields into one single-channel atlas that a scene's TextPass
// (text/text_pass.h) samples. Everything is measured in em (the font size), x right and y down, with
// the origin at the start of the line on the baseline, so a layout is drawn at any size from one
// atlas and stays crisp.
//
//   text::Font italic = text::Font::fromAssets(context.assets, "FrauncesItalic");
//   text::GlyphAtlas atlas;
//   text::TextLayout chroma = atlas.layout(italic, "CHROMA");     // glyphs rasterised once
//   text::TextLayout again = atlas.layout(italic, "CHROMA");      // nothing added
//
// A font that is missing or that FreeType cannot read is replaced by DejaVu Serif, and problem()
// names the file, why and what stands in. Fonts and atlases are not thread-safe.
#include "core/assets.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace vitrine::text {

// The face that stands in for a missing or unreadable font (Debian's fonts-dejavu-core).
inline constexpr const char* kFallbackFace = "/usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf";

struct Shaping {
  // Letter-spacing in em added after every glyph but the last (small caps want 0.05 to 0.15). While
  // it is not zero, optional ligatures are off, as CSS does for letter-spacing: "fi" stays two letters.
  float trackingEm = 0.0f;
};

// One glyph placed by shaping.
struct ShapedGlyph {
  uint32_t glyph = 0;    // glyph index in the face
  uint32_t cluster = 0;  // byte offset in the UTF-8 string of the first character it shows
  glm::vec2 pen{0.0f};   // em from the start of the line to the glyph's origin (kerning included)
  float advance = 0.0f;  // em to the next glyph's origin: kerning and tracking included
};

// A glyph's signed distance field as FreeType renders it: 8 bits, top row first. A texel v (0..255)
// holds the distance (v - 128) / 128 * spread pixels at the rendered size, positive inside; 128 is
// the outline, 0 and 255 are `spread` pixels or more outside and inside.
struct GlyphSdf {
  uint32_t width = 0, height = 0;  // 0 x 0 for a glyph without ink (a space)
  std::vector<uint8_t> texels;
  glm::vec2 offset{0.0f};  // em from the glyph origin to the bitmap's top-left corner
  glm::vec2 size{0.0f};    // em the bitmap covers: width and height / pxPerEm
  glm::vec2 inkMin{0.0f}, inkMax{0.0f};  // the outline's bounding box, em from the glyph origin
};

class Font {
 public:
  // Never throws: a file that is missing or unreadable is replaced by `fallback`, and problem() says
  // so. When the fallback cannot be read either, the font is not usable() and shapes to nothing.
  static Font load(const std::filesystem::path& path, const std::filesystem::path& fallback = kFallbackFace);
  // A fetched font by family ("Fraunces", "FrauncesItalic", "CormorantSC"). A file that is there but
  // unreadable is reported through assets.reportMissing; an absent one is already in assets.missing().
  static Font fromAssets(const Assets& assets, const std::string& family);

  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;
  ~Font();

  bool usable() const;
  bool isFallback() const;  // the glyphs come from the fallback face
  // Empty when the requested file serves; otherwise "PATH: WHY; using DejaVu Serif (FALLBACK)".
  const std::string& problem() const;
  const std::filesystem::path& path() const;  // the file the glyphs come from
  std::string name() const;                   // family and style: "Fraunces Medium Italic"
  uint32_t id() const;                        // unique per loaded font: keys its glyphs in an atlas
  float ascender() const;                     // em above the baseline
  float descender() const;                    // em below the baseline (positive)

  // Positioned glyphs in logical order (kerning, ligatures and marks as the font's tables say).
  std::vector<ShapedGlyph> shape(std::string_view utf8, const Shaping& shaping = {}) const;
  // The advance from the horizontal metrics alone, no kerning: what shaping is measured against.
  float plainAdvance(uint32_t glyph) const;
  uint32_t glyphFor(char32_t codepoint) const;  // 0 (.notdef) when the face lacks it
  // FreeType's SDF render mode at `pxPerEm` with `spreadPx` (1 to 16) pixels of distance around the
  // outline, from the glyph rasterised at twice the size so that overlapping contours are one shape.
  // A glyph FreeType cannot load or render comes back empty.
  GlyphSdf renderSdf(uint32_t glyph, uint32_t pxPerEm, uint32_t spreadPx) const;

 private:
  struct Impl;
  explicit Font(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

struct AtlasOptions {
  uint32_t width = 1024, height = 512;  // R8 texels
  uint32_t pxPerEm = 64;                // the size glyphs are rasterised at
  uint32_t spreadPx = 10;               // distance kept around each outline (1 to 16): the glow's reach
  uint32_t gutterPx = 1;                // empty texels between glyphs, so linear filtering stays inside
};

// A glyph's place in the atlas.
struct AtlasGlyph {
  uint32_t x = 0, y = 0, width = 0, height = 0;  // texels; 0 x 0 for a glyph without ink
  glm::vec2 offset{0.0f}, size{0.0f};            // em: the bitmap relative to the glyph origin
  glm::vec2 inkMin{0.0f}, inkMax{0.0f};          // em: the outline's box relative to the glyph origin
};

// One glyph of a layout: the rectangle its distance field covers and where that lies in the atlas.
struct GlyphQuad {
  glm::vec2 min{0.0f}, max{0.0f};      // em from the layout's origin (start of the line, on the baseline)
  glm::vec2 uvMin{0.0f}, uvMax{0.0f};  // atlas coordinates 0..1
  uint32_t cluster = 0;                // byte offset of the character it shows
};

// A string ready to draw at any size: its glyphs with ink, in reading order (a type-in reveals them
// in this order), and the ink's bounding box.
struct TextLayout {
  std::vector<GlyphQuad> quads;
  glm::vec2 inkMin{0.0f}, inkMax{0.0f};  // em from the origin; both 0 when nothing has ink
  float advance = 0.0f;                  // em from the origin to where the next string would start
  float reachEm = 0.0f;                  // how far outside the ink the distance field reaches
  bool empty() const { return quads.empty(); }
  glm::vec2 inkCentre() const { return (inkMin + inkMax) * 0.5f; }
};

// Glyph distance fields packed on shelves into one R8 image. A glyph is rasterised the first time a
// layout needs it; laying out the same word again adds nothing.
class GlyphAtlas {
 public:
  explicit GlyphAtlas(const AtlasOptions& options = {});

  // Shapes and places `utf8`, adding the glyphs the atlas lacks. Throws vitrine::Error when a new
  // glyph does not fit, naming the atlas size.
  TextLayout layout(const Font& font, std::string_view utf8, const Shaping& shaping = {});
  const AtlasGlyph& glyph(const Font& font, uint32_t glyph);       // adds it when absent
  const AtlasGlyph* find(const Font& font, uint32_t glyph) const;  // null when absent

  const AtlasOptions& options() const { return options_; }
  uint32_t width() const { return options_.width; }
  uint32_t height() const { return options_.height; }
  std::span<const uint8_t> texels() const { return texels_; }  // width * height, top row first
  size_t glyphCount() const { return glyphs_.size(); }
  uint64_t revision() const { return revision_; }  // changes whenever texels are added
  float reachEm() const { return float(options_.spreadPx) / float(options_.pxPerEm); }
  // Signed distance in em (positive inside) held by a sampled texel value 0..1.
  float distanceEm(float value) const { return (value * 255.0f - 128.0f) / 128.0f * reachEm(); }
  // The atlas sampled bilinearly, clamped, at texel centres: what the text pass's linear sampler
  // returns on the GPU, for checking its output on the CPU.
  float sampleLinear(glm::vec2 uv) const;

 private:
  struct Shelf {
    uint32_t y, height, x;
  };
  bool place(uint32_t width, uint32_t height, uint32_t& x, uint32_t& y);
  AtlasOptions options_;
  std::vector<uint8_t> texels_;
  std::vector<Shelf> shelves_;
  std::unordered_map<uint64_t, AtlasGlyph> glyphs_;  // (font id << 32) | glyph index
  uint64_t revision_ = 0;
};

}  // namespace vitrine::text
