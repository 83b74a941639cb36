// Font files through the text module (src/text/font.h) as scenes use them: load, shape, lay out into
// an atlas (rasterising distance fields) and render a glyph. The stand-in face is left out (an empty
// fallback path) so that every input exercises the file's own tables, not DejaVu's.
#include "core/error.h"
#include "support/temp_file.h"
#include "text/font.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

using namespace vitrine;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const text::Font font = text::Font::load(fuzz::writeTempFile("font.ttf", data, size), "");
  if (!font.usable()) {
    if (font.problem().empty()) {
      std::fprintf(stderr, "font: an unusable font without a problem\n");
      std::abort();
    }
    return 0;
  }
  font.ascender();
  font.descender();
  font.name();
  // Small atlas: enough for a few glyphs at a small size, so a run stays fast.
  text::GlyphAtlas atlas({.width = 128, .height = 64, .pxPerEm = 16, .spreadPx = 4});
  try {
    for (const char* words : {"Vitrine", "fi AVAV", "\xc3\xa9\xe2\x80\x94\xef\xac\x81"}) {
      const text::TextLayout layout = atlas.layout(font, words, {.trackingEm = words[0] == 'f' ? 0.1f : 0.0f});
      for (const auto& quad : layout.quads)
        if (!(quad.uvMin.x >= 0.0f && quad.uvMax.x <= 1.0f && quad.uvMin.y >= 0.0f && quad.uvMax.y <= 1.0f)) {
          std::fprintf(stderr, "font: a glyph's atlas rectangle lies outside the atlas\n");
          std::abort();
        }
    }
  } catch (const Error&) {  // the atlas is full: a documented refusal
  }
  font.renderSdf(font.glyphFor('g'), 24, 6);
  return 0;
}
