// src/text/font.*: shaping with HarfBuzz, distance fields from FreeType packed once into an atlas, and
// the fallback face standing in for a font that is missing or cut short.
#include "core/error.h"
#include "text/font.h"

#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <glm/common.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

namespace vitrine::text {
namespace {

const std::filesystem::path kDejaVu = kFallbackFace;

std::string readAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The fetched fonts where scripts/setup put them, and DejaVu Serif, which is always there.
std::vector<std::filesystem::path> faces() {
  std::vector<std::filesystem::path> found{kDejaVu};
  const Assets assets = Assets::locate();
  for (const char* family : {"Fraunces", "FrauncesItalic", "CormorantSC"})
    if (auto path = assets.font(family)) found.push_back(*path);
  return found;
}

class Text : public test::TempFolderTest {
 protected:
  void SetUp() override {
    TempFolderTest::SetUp();
    if (!std::filesystem::exists(kDejaVu)) GTEST_SKIP() << kDejaVu << " is not installed (fonts-dejavu-core)";
  }
  std::filesystem::path write(const std::string& name, const std::string& bytes) const {
    std::ofstream(folder_ / name, std::ios::binary) << bytes;
    return folder_ / name;
  }
};

glm::vec2 uvAt(const GlyphQuad& quad, glm::vec2 em) {
  return glm::mix(quad.uvMin, quad.uvMax, (em - quad.min) / (quad.max - quad.min));
}

TEST_F(Text, ShapingPlacesGlyphsLeftToRight) {
  for (const auto& path : faces()) {
    const Font font = Font::load(path);
    ASSERT_TRUE(font.problem().empty()) << font.problem();
    const auto glyphs = font.shape("CRIMSON CHROMA");
    ASSERT_EQ(glyphs.size(), 14u) << path;
    for (size_t i = 1; i < glyphs.size(); ++i) {
      EXPECT_GT(glyphs[i].pen.x, glyphs[i - 1].pen.x) << path << " glyph " << i;
      EXPECT_EQ(glyphs[i].cluster, i) << "one glyph per letter, in order";
    }
    EXPECT_EQ(glyphs[0].pen, glm::vec2(0.0f));
    if (path == kDejaVu) {
      EXPECT_NEAR(glyphs[0].advance, font.plainAdvance(glyphs[0].glyph), 1e-4f) << "DejaVu does not kern C and R";
    }
  }
}

// "AV" is kerned in every one of these faces: A's advance is shorter than its horizontal metrics say.
TEST_F(Text, ShapingKernsWhereTheFontKerns) {
  for (const auto& path : faces()) {
    const Font font = Font::load(path);
    const auto glyphs = font.shape("AV");
    ASSERT_EQ(glyphs.size(), 2u);
    const float plain = font.plainAdvance(glyphs[0].glyph);
    EXPECT_GT(plain, 0.3f) << path;
    EXPECT_LT(glyphs[0].advance, plain - 0.02f) << path << ": A and V are kerned together";
    EXPECT_NEAR(glyphs[1].pen.x, glyphs[0].advance, 1e-6f);
    const auto apart = font.shape("A V");  // a space between: nothing to kern
    EXPECT_NEAR(apart[0].advance, plain, 1e-4f) << path;
  }
}

TEST_F(Text, TrackingSpacesLettersAndKeepsLigaturesApart) {
  const Font font = Font::load(kDejaVu);
  const auto plain = font.shape("AMBER");
  const auto tracked = font.shape("AMBER", {0.1f});
  ASSERT_EQ(tracked.size(), plain.size());
  for (size_t i = 0; i < plain.size(); ++i) EXPECT_NEAR(tracked[i].pen.x - plain[i].pen.x, 0.1f * float(i), 1e-5f);
  EXPECT_NEAR(tracked.back().advance, plain.back().advance, 1e-6f) << "no tracking after the last letter";
  EXPECT_EQ(font.shape("fi").size(), 1u) << "DejaVu Serif joins f and i";
  EXPECT_EQ(font.shape("fi", {0.05f}).size(), 2u) << "letter-spacing keeps optional ligatures apart";
}

TEST_F(Text, AtlasHoldsEachGlyphOnce) {
  const Font font = Font::load(kDejaVu);
  GlyphAtlas atlas;
  const TextLayout first = atlas.layout(font, "CHROMA");
  EXPECT_EQ(first.quads.size(), 6u);
  EXPECT_EQ(atlas.glyphCount(), 6u);
  const uint64_t revision = atlas.revision();
  const auto texels = std::vector<uint8_t>(atlas.texels().begin(), atlas.texels().end());
  const TextLayout again = atlas.layout(font, "CHROMA");
  EXPECT_EQ(atlas.glyphCount(), 6u) << "laying out the same word again adds nothing";
  EXPECT_EQ(atlas.revision(), revision);
  EXPECT_TRUE(std::equal(texels.begin(), texels.end(), atlas.texels().begin()));
  for (size_t i = 0; i < first.quads.size(); ++i) EXPECT_EQ(first.quads[i].uvMin, again.quads[i].uvMin);

  // CRIMSON shares C, R, M and O with CHROMA: only I, S and N are new. The space has no ink.
  atlas.layout(font, "CRIMSON ROSE");
  EXPECT_EQ(atlas.glyphCount(), 6u + 3u + 1u + 1u) << "I, S, N, the space and E";
  std::set<std::pair<float, float>> places;
  const TextLayout crimson = atlas.layout(font, "CRIMSON");
  for (const auto& quad : crimson.quads) places.insert({quad.uvMin.x, quad.uvMin.y});
  EXPECT_EQ(places.size(), 7u) << "C, R, I, M, S, O and N each have their own place";
  EXPECT_EQ(crimson.quads[0].uvMin, first.quads[0].uvMin) << "C is the same atlas entry in both words";

  // The same glyph index in another font is another glyph.
  const Font other = Font::load(kDejaVu);
  atlas.layout(other, "C");
  EXPECT_EQ(atlas.glyphCount(), 12u);
}

// Rectangles do not overlap and stay inside the atlas.
TEST_F(Text, AtlasPacksGlyphsApart) {
  GlyphAtlas atlas({2048, 1024});
  std::vector<AtlasGlyph> placed;
  for (const auto& path : faces()) {
    const Font font = Font::load(path);
    for (const ShapedGlyph& shaped : font.shape("ABCDEFGHIJKLMNOPQRSTUVWXYZ")) placed.push_back(atlas.glyph(font, shaped.glyph));
  }
  for (size_t i = 0; i < placed.size(); ++i) {
    const AtlasGlyph& a = placed[i];
    EXPECT_LE(a.x + a.width, atlas.width());
    EXPECT_LE(a.y + a.height, atlas.height());
    for (size_t j = i + 1; j < placed.size(); ++j) {
      const AtlasGlyph& b = placed[j];
      const bool apart = a.x + a.width <= b.x || b.x + b.width <= a.x || a.y + a.height <= b.y || b.y + b.height <= a.y;
      EXPECT_TRUE(apart) << i << " and " << j;
    }
  }
}

TEST_F(Text, AtlasThatIsFullSaysSo) {
  const Font font = Font::load(kDejaVu);
  GlyphAtlas atlas({128, 96});
  EXPECT_THROW(atlas.layout(font, "ABCDEFGHIJ"), Error);
}

// The distance field is 0.5 on the outline (checked at the outline's on-curve points, read from the
// font with FreeType), above 0.5 inside and below outside. DejaVu Serif's contours never overlap, so
// every on-curve point lies on the outline of the letter.
TEST_F(Text, DistanceFieldIsHalfOnTheOutline) {
  const Font font = Font::load(kDejaVu);
  GlyphAtlas atlas;
  FT_Library library;
  ASSERT_EQ(FT_Init_FreeType(&library), 0);
  FT_Face face;
  ASSERT_EQ(FT_New_Face(library, kDejaVu.c_str(), 0, &face), 0);
  const float upem = float(face->units_per_EM);
  for (const char letter : std::string("IOVSg")) {
    const TextLayout layout = atlas.layout(font, std::string(1, letter));
    ASSERT_EQ(layout.quads.size(), 1u);
    const GlyphQuad& quad = layout.quads[0];
    ASSERT_EQ(FT_Load_Char(face, FT_ULong(letter), FT_LOAD_NO_SCALE), 0);
    const FT_Outline& outline = face->glyph->outline;
    std::vector<float> errors;
    for (int i = 0; i < outline.n_points; ++i) {
      if (!(outline.tags[i] & 1)) continue;  // off-curve control points are not on the outline
      const glm::vec2 em(float(outline.points[i].x) / upem, -float(outline.points[i].y) / upem);
      errors.push_back(std::abs(atlas.sampleLinear(uvAt(quad, em)) - 0.5f));
    }
    ASSERT_GT(errors.size(), 3u);
    std::sort(errors.begin(), errors.end());
    // A texel of the 64 px field moves the value by 1/20 (spread 10 px). On-curve points are mostly
    // corners, which linear filtering of a distance field rounds: the outline is found within 0.4
    // texel typically, within one at the sharpest corners (V's apex, g's ear).
    EXPECT_LT(errors[errors.size() / 2], 0.02f) << "'" << letter << "'";
    EXPECT_LT(errors.back(), 0.05f) << "'" << letter << "'";

    const float outside = atlas.sampleLinear(uvAt(quad, quad.min + 0.01f));  // the padded corner
    EXPECT_LT(outside, 0.05f) << "'" << letter << "'";
    EXPECT_LT(atlas.distanceEm(outside), -0.9f * atlas.reachEm());
    if (letter == 'I') {  // the middle of the stem is inside
      const float inside = atlas.sampleLinear(uvAt(quad, layout.inkCentre()));
      EXPECT_GT(inside, 0.55f);
      EXPECT_GT(atlas.distanceEm(inside), 0.01f);
    }
    if (letter == 'O') {  // the middle of the bowl is outside, in the counter
      EXPECT_LT(atlas.sampleLinear(uvAt(quad, layout.inkCentre())), 0.45f);
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(library);
}

// The fetched fonts are static instances of variable fonts: their letters are built of overlapping
// contours. The field must see one shape (no seam where contours cross, no counter cut out of a
// stem): wherever FreeType's ordinary rasteriser covers a texel fully, the field says inside, and
// wherever it covers nothing, outside.
TEST_F(Text, OverlappingContoursMakeOneShape) {
  for (const auto& path : faces()) {
    const Font font = Font::load(path);
    GlyphAtlas atlas;
    FT_Library library;
    ASSERT_EQ(FT_Init_FreeType(&library), 0);
    FT_Face face;
    ASSERT_EQ(FT_New_Face(library, path.c_str(), 0, &face), 0);
    ASSERT_EQ(FT_Set_Pixel_Sizes(face, 0, atlas.options().pxPerEm), 0);
    for (const char letter : std::string("ABEHKMQRV")) {
      const TextLayout layout = atlas.layout(font, std::string(1, letter));
      ASSERT_EQ(layout.quads.size(), 1u);
      ASSERT_EQ(FT_Load_Char(face, FT_ULong(letter), FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP), 0);
      face->glyph->outline.flags |= FT_OUTLINE_OVERLAP;
      ASSERT_EQ(FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL), 0);
      const FT_Bitmap& coverage = face->glyph->bitmap;
      const float px = float(atlas.options().pxPerEm);
      int wrong = 0, full = 0;
      for (unsigned y = 0; y < coverage.rows; ++y)
        for (unsigned x = 0; x < coverage.width; ++x) {
          const int covered = coverage.buffer[y * unsigned(coverage.pitch) + x];
          if (covered != 0 && covered != 255) continue;  // on the edge
          const glm::vec2 em(float(face->glyph->bitmap_left + int(x)) + 0.5f,
                             -float(face->glyph->bitmap_top - int(y)) + 0.5f);
          const float value = atlas.sampleLinear(uvAt(layout.quads[0], em / px));
          if (covered == 255) ++full;
          if ((covered == 255) != (value > 0.5f)) ++wrong;
        }
      EXPECT_GT(full, 50) << path << " '" << letter << "'";
      EXPECT_EQ(wrong, 0) << path << " '" << letter << "'";
    }
    FT_Done_Face(face);
    FT_Done_FreeType(library);
  }
}

TEST_F(Text, LayoutInkBoxAndQuadsAgree) {
  const Font font = Font::load(kDejaVu);
  GlyphAtlas atlas;
  const TextLayout layout = atlas.layout(font, "CHROMA", {0.05f});
  EXPECT_NEAR(layout.reachEm, 10.0f / 64.0f, 1e-6f);
  EXPECT_LT(layout.inkMin.y, -0.6f) << "capitals rise above the baseline (y down)";
  EXPECT_GT(layout.inkMax.y, -0.05f);
  EXPECT_LT(layout.inkMax.y, 0.05f) << "and sit on it";
  EXPECT_NEAR(layout.inkMin.x, layout.quads[0].min.x + layout.reachEm, 2.0f / 64.0f);
  EXPECT_GT(layout.advance, layout.inkMax.x - 0.1f);
  for (const GlyphQuad& quad : layout.quads) {
    EXPECT_LE(quad.min.x, layout.inkMax.x);
    EXPECT_GE(quad.max.x, layout.inkMin.x);
  }
  EXPECT_TRUE(atlas.layout(font, "   ").empty());
  EXPECT_TRUE(atlas.layout(font, "").empty());
}

TEST_F(Text, MissingFontFallsBackToDejaVuAndNamesThePath) {
  const auto absent = folder_ / "Fraunces.woff2";
  const Font font = Font::load(absent);
  EXPECT_TRUE(font.usable());
  EXPECT_TRUE(font.isFallback());
  EXPECT_EQ(font.path(), kDejaVu);
  EXPECT_EQ(font.problem(), absent.string() + ": not found; using DejaVu Serif (" + kDejaVu.string() + ")");
  EXPECT_EQ(font.shape("CHROMA").size(), 6u) << "the stand-in shapes the text";

  // Through the assets: an absent font is listed by Assets::missing() already, not reported twice.
  const Assets assets(folder_);
  const Font fromAssets = Font::fromAssets(assets, "FrauncesItalic");
  EXPECT_TRUE(fromAssets.isFallback());
  EXPECT_NE(fromAssets.problem().find("FrauncesItalic.woff2: not found"), std::string::npos) << fromAssets.problem();
  const auto missing = assets.missing();
  EXPECT_EQ(std::count_if(missing.begin(), missing.end(),
                          [](const std::string& line) { return line.find("FrauncesItalic") != std::string::npos; }),
            1);
}

TEST_F(Text, TruncatedFontIsReportedNotACrash) {
  const std::string bytes = readAll(kDejaVu);
  const auto half = write("Half.ttf", bytes.substr(0, bytes.size() / 2));
  const auto header = write("Header.woff2", std::string("wOF2\0\1\0\0", 8) + std::string(40, '\0'));
  const auto text = write("Text.ttf", "not a font at all");
  for (const auto& path : {half, header, text}) {
    const Font font = Font::load(path);
    EXPECT_TRUE(font.isFallback()) << path;
    EXPECT_EQ(font.problem().rfind(path.string() + ": ", 0), 0u) << font.problem();
    EXPECT_NE(font.problem().find("; using DejaVu Serif"), std::string::npos) << font.problem();
    GlyphAtlas atlas;
    EXPECT_EQ(atlas.layout(font, "AMBER").quads.size(), 5u);
  }
  EXPECT_EQ(Font::load(text).problem(), text.string() + ": unknown file format; using DejaVu Serif (" +
                                            kDejaVu.string() + ")");
  // A fetched WOFF2 cut short, where there is one.
  if (const auto italic = Assets::locate().font("FrauncesItalic")) {
    const std::string woff2 = readAll(*italic);
    const auto cut = write("FrauncesItalic.woff2", woff2.substr(0, woff2.size() / 2));
    const Font font = Font::load(cut);
    EXPECT_TRUE(font.isFallback());
    EXPECT_EQ(font.problem().rfind(cut.string() + ": ", 0), 0u) << font.problem();
  }

  // A fetched font cut short is reported through the assets, once, for the gallery to list.
  std::filesystem::create_directories(folder_ / "fonts");
  std::ofstream(folder_ / "fonts" / "CormorantSC.woff2", std::ios::binary) << bytes.substr(0, 300);
  const Assets assets(folder_);
  const Font cut = Font::fromAssets(assets, "CormorantSC");
  const Font again = Font::fromAssets(assets, "CormorantSC");
  EXPECT_TRUE(cut.isFallback());
  const auto missing = assets.missing();
  EXPECT_EQ(std::count(missing.begin(), missing.end(), cut.problem()), 1) << cut.problem();

  // Neither the file nor the fallback: nothing to draw, and it says so.
  const Font none = Font::load(text, folder_ / "absent.ttf");
  EXPECT_FALSE(none.usable());
  EXPECT_NE(none.problem().find("no text is drawn"), std::string::npos) << none.problem();
  GlyphAtlas atlas;
  EXPECT_TRUE(atlas.layout(none, "AMBER").empty());
}

}  // namespace
}  // namespace vitrine::text

namespace vitrine::text {
namespace {

// A fuzzed font (tests/fuzz-regressions/font/) with a glyph whose outline spans far more than an em:
// FreeType's distance transform spent over 10 s on it. Such a glyph is refused as no ink, at once.
TEST(FontFuzzRegressions, AGlyphSpanningManyEmsIsNoInkNotAStall) {
  const auto start = std::chrono::steady_clock::now();
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(VITRINE_FUZZ_REGRESSION_DIR) / "font")) {
    const Font font = Font::load(entry.path(), "");
    if (!font.usable()) continue;
    GlyphAtlas atlas({.width = 128, .height = 64, .pxPerEm = 16, .spreadPx = 4});
    try {
      for (const char* words : {"Vitrine", "fi AVAV"}) atlas.layout(font, words, {});
    } catch (const Error&) {  // a full atlas is a refusal, not a stall
    }
    font.renderSdf(font.glyphFor('g'), 24, 6);
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
}

}  // namespace
}  // namespace vitrine::text
