// text/text_pass.*: type drawn by a scene's own compute pass, under the validation layer. A small scene
// clears its target and draws the words; the read-back is compared with the atlas's distance field
// on the CPU: inside the ink the text's colour, away from it the background, untouched outside the
// draw's box. Pictures of what is drawn go to build/text-out/ for a look.
#include "host/scene_renderer.h"
#include "image/image.h"
#include "image/image_io.h"
#include "support/gpu_test.h"
#include "support/test_scene.h"
#include "text/text_pass.h"

#include <fmt/format.h>
#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

namespace vitrine::test {
namespace {

const text::Shaping kSmallCaps{0.08f};

// Cormorant SC and Fraunces italic (or DejaVu Serif where they were not fetched), the words of the
// bloom scene in the atlas from the start; the test sets the background and the draws.
class TextScene final : public TestScene {
 public:
  explicit TextScene(const SceneContext& context)
      : cormorant(text::Font::fromAssets(context.assets, "CormorantSC")),
        italic(text::Font::fromAssets(context.assets, "FrauncesItalic")),
        pass(context, {{&cormorant, {"AMBER", "ROSE", "CRIMSON"}, kSmallCaps}, {&italic, {"CHROMA"}, {}}}) {}

  void record(const FrameContext& frame) override {
    frame.transition(frame.target, gpu::use::TransferDst);
    const VkClearColorValue clear{{background.r, background.g, background.b, background.a}};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(frame.cmd, frame.target.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);
    pass.record(frame, draws);
  }

  text::Font cormorant, italic;
  text::TextPass pass;
  glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
  std::vector<text::TextDraw> draws;
};

TextScene* lastTextScene = nullptr;
const TestSceneEntry& kTextScene = testScene(lastTextScene);

// One frame at a time through the host's scene renderer, the target read back once it is done.
class TextFrames {
 public:
  explicit TextFrames(const gpu::Device& device)
      : device_(device), assets_(Assets::locate()), programs_(device), renderer_(device, programs_, assets_, 1) {
    renderer_.setScene(kTextScene.info, kTextScene.create);
    scene_ = lastTextScene;
  }
  ~TextFrames() { device_.waitIdle(); }

  TextScene& scene() { return *scene_; }

  ImageRgba render(VkExtent2D size) {
    gpu::ImageDesc desc;
    desc.extent = {size.width, size.height, 1};
    desc.usage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    gpu::Image output(device_, desc, "text test output");
    gpu::Buffer staging(device_, VkDeviceSize(size.width) * size.height * 8, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        gpu::MemoryUse::Readback, "text test readback");
    device_.submitNow([&](VkCommandBuffer cmd) {
      FrameInput input;
      input.frame = frames_++;
      renderer_.record(cmd, 0, input,
                       host::BlitDestination{output.handle(), size, gpu::use::Discard, gpu::use::TransferDst});
      gpu::recordReadback(cmd, renderer_.target(), staging);
    });
    staging.invalidate();
    return imageFromHalves(size.width, size.height, staging.view<const uint16_t>());
  }

 private:
  const gpu::Device& device_;
  Assets assets_;
  gpu::ProgramLibrary programs_;
  host::SceneRenderer renderer_;
  TextScene* scene_ = nullptr;
  uint64_t frames_ = 0;
};

// Signed distance in target pixels from pixel (x, y)'s centre to the draw's ink, positive inside
// (the CPU's reading of the same field); far outside when no glyph's square holds the pixel.
float inkDistancePx(const text::GlyphAtlas& atlas, const text::TextDraw& draw, VkExtent2D extent, int x, int y) {
  glm::vec2 origin = draw.position * (draw.normalized ? glm::vec2(float(extent.width), float(extent.height)) : glm::vec2(1.0f));
  if (draw.anchor == text::Anchor::InkCentre) origin -= draw.layout->inkCentre() * draw.sizePx;
  const glm::vec2 em = (glm::vec2(float(x), float(y)) + 0.5f - origin) / draw.sizePx;
  float best = -1e9f;
  for (const text::GlyphQuad& quad : draw.layout->quads) {
    if (em.x < quad.min.x || em.y < quad.min.y || em.x >= quad.max.x || em.y >= quad.max.y) continue;
    const glm::vec2 uv = glm::mix(quad.uvMin, quad.uvMax, (em - quad.min) / (quad.max - quad.min));
    best = std::max(best, atlas.distanceEm(atlas.sampleLinear(uv)) * draw.sizePx);
  }
  return best;
}

bool near(const float* pixel, glm::vec4 colour, float tolerance) {
  for (int c = 0; c < 4; ++c)
    if (std::abs(pixel[c] - colour[c]) > tolerance) return false;
  return true;
}

void writeLook(const std::string& name, const ImageRgba& image) {
  const std::filesystem::path folder = VITRINE_TEXT_OUTPUT_DIR;
  std::filesystem::create_directories(folder);
  writeImage(folder / (name + ".png"), image);
}

class TextPass : public GpuTest {};

TEST_F(TextPass, ChromaCoversItsInkAndLeavesTheRestAlone) {
  TextFrames frames(device());
  TextScene& scene = frames.scene();
  const text::TextLayout chroma = scene.pass.layout(scene.italic, "CHROMA");
  const size_t glyphs = scene.pass.atlas().glyphCount();
  scene.background = {0.1f, 0.2f, 0.3f, 1.0f};
  const glm::vec4 colour{0.9f, 0.5f, 0.2f, 1.0f};
  scene.draws = {{&chroma, {160.0f, 80.0f}, false, 64.0f, colour}};
  const VkExtent2D extent{320, 160};
  const ImageRgba image = frames.render(extent);
  EXPECT_EQ(scene.pass.atlas().glyphCount(), glyphs) << "CHROMA was in the atlas from the start";
  writeLook("chroma", image);

  const glm::vec4 background(image.at(0, 0)[0], image.at(0, 0)[1], image.at(0, 0)[2], image.at(0, 0)[3]);
  EXPECT_TRUE(near(image.at(0, 0), scene.background, 1e-3f)) << "the clear, as half floats";
  const text::PixelBox box = text::TextPass::bounds(scene.draws[0], extent);
  ASSERT_FALSE(box.empty());
  EXPECT_LT(box.x1 - box.x0, 300);
  EXPECT_LT(box.y1 - box.y0, 80);
  int inside = 0, outside = 0, untouched = 0, wrong = 0;
  for (int y = 0; y < int(extent.height); ++y)
    for (int x = 0; x < int(extent.width); ++x) {
      const float* pixel = image.at(uint32_t(x), uint32_t(y));
      const bool inBox = x >= box.x0 && x < box.x1 && y >= box.y0 && y < box.y1;
      const float distance = inkDistancePx(scene.pass.atlas(), scene.draws[0], extent, x, y);
      if (!inBox || distance < -1.5f) {  // exactly the background: not written at all
        const bool same = std::equal(pixel, pixel + 4, &background[0]);
        (inBox ? outside : untouched) += 1;
        if (!same && ++wrong <= 5) ADD_FAILURE() << "pixel " << x << "," << y << " changed, " << distance << " px from the ink";
      } else if (distance > 1.5f) {
        ++inside;
        if (!near(pixel, colour, 2e-3f) && ++wrong <= 5)
          ADD_FAILURE() << "pixel " << x << "," << y << " is " << pixel[0] << "," << pixel[1] << "," << pixel[2]
                        << ", " << distance << " px inside the ink";
      }
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(inside, 600) << "the letters have ink";
  EXPECT_GT(outside, 3000) << "and counters and gaps";
  EXPECT_GT(untouched, 320 * 160 / 2);
}

// The edge is as wide in pixels at 96 px as at 48 px: the partly covered pixels double with the
// outline's length (twice the size) instead of quadrupling as a blur that scaled with the text would.
TEST_F(TextPass, TwiceTheSizeIsAsCrisp) {
  TextFrames frames(device());
  TextScene& scene = frames.scene();
  const text::TextLayout chroma = scene.pass.layout(scene.italic, "CHROMA");
  const glm::vec4 colour{1.0f, 1.0f, 1.0f, 1.0f};
  auto edge = [&](float size) {
    scene.draws = {{&chroma, {0.5f, 0.5f}, true, size, colour}};
    const ImageRgba image = frames.render({640, 200});
    writeLook(fmt::format("chroma_{}px", int(size)), image);
    int partial = 0, crossings = 0;
    for (uint32_t y = 0; y < image.height; ++y) {
      bool wasInk = false;
      for (uint32_t x = 0; x < image.width; ++x) {
        const float value = image.at(x, y)[0];
        if (value > 0.05f && value < 0.95f) ++partial;
        const bool ink = value >= 0.5f;
        if (ink != wasInk) ++crossings;
        wasInk = ink;
      }
    }
    return std::pair{partial, float(partial) / float(std::max(crossings, 1))};
  };
  const auto [small, smallWidth] = edge(48.0f);
  const auto [large, largeWidth] = edge(96.0f);
  EXPECT_GT(small, 100);
  const float ratio = float(large) / float(small);
  EXPECT_GT(ratio, 1.5f);
  EXPECT_LT(ratio, 2.6f) << "twice the outline, the same edge: about twice the partly covered pixels";
  EXPECT_LT(smallWidth, 2.0f) << "partly covered pixels per edge crossed along a row";
  EXPECT_LT(largeWidth, 2.0f);
  EXPECT_NEAR(largeWidth, smallWidth, 0.5f);
  // Softness widens the edge on purpose: 0.05 em each side at 96 px is some 10 pixels across.
  scene.draws = {{&chroma, {0.5f, 0.5f}, true, 96.0f, colour}};
  scene.draws[0].softnessEm = 0.05f;
  const ImageRgba soft = frames.render({640, 200});
  writeLook("chroma_96px_soft", soft);
  int softPartial = 0;
  for (float value : soft.pixels) softPartial += value > 0.05f && value < 0.95f;
  EXPECT_GT(softPartial / 3, 4 * large) << "rgb of each partly covered pixel";
}

// A type-in at 50 %: the first three of AMBER's five letters are drawn (the third fading in), the
// last two not at all.
TEST_F(TextPass, TypeInRevealsGlyphsInReadingOrder) {
  TextFrames frames(device());
  TextScene& scene = frames.scene();
  const text::TextLayout amber = scene.pass.layout(scene.cormorant, "AMBER", kSmallCaps);
  ASSERT_EQ(amber.quads.size(), 5u);
  const glm::vec4 colour{1.0f, 0.6f, 0.2f, 1.0f};
  text::TextDraw draw{&amber, {40.0f, 80.0f}, false, 60.0f, colour};
  draw.reveal = 0.5f;
  draw.anchor = text::Anchor::Baseline;
  scene.draws = {draw};
  const VkExtent2D extent{400, 120};
  const ImageRgba image = frames.render(extent);
  writeLook("amber_typing", image);
  const glm::vec2 origin = draw.position;  // the start of the baseline
  int below = 0;  // capitals stand on the baseline: no ink under it
  for (uint32_t y = 84; y < extent.height; ++y)
    for (uint32_t x = 0; x < extent.width; ++x) below += image.at(x, y)[0] > 0.0f;
  EXPECT_EQ(below, 0);
  auto inkIn = [&](const text::GlyphQuad& quad) {  // ink pixels within a glyph's ink columns
    int count = 0;
    const int x0 = int(origin.x + (quad.min.x + amber.reachEm) * draw.sizePx);
    const int x1 = int(origin.x + (quad.max.x - amber.reachEm) * draw.sizePx);
    for (int y = 0; y < int(extent.height); ++y)
      for (int x = std::max(x0, 0); x < std::min(x1, int(extent.width)); ++x) count += image.at(uint32_t(x), uint32_t(y))[0] > 0.5f;
    return count;
  };
  EXPECT_GT(inkIn(amber.quads[0]), 100) << "A";
  EXPECT_GT(inkIn(amber.quads[1]), 100) << "M";
  // B is half revealed: drawn at half strength.
  float strongest = 0.0f;
  for (uint32_t y = 0; y < extent.height; ++y)
    for (uint32_t x = uint32_t(origin.x + (amber.quads[2].min.x + amber.reachEm) * draw.sizePx);
         x < uint32_t(origin.x + (amber.quads[2].max.x - amber.reachEm) * draw.sizePx); ++x)
      strongest = std::max(strongest, image.at(x, y)[0]);
  EXPECT_NEAR(strongest, 0.5f, 0.02f) << "B fades in";
  float rest = 0.0f;  // E and R: nothing
  for (uint32_t y = 0; y < extent.height; ++y)
    for (uint32_t x = uint32_t(origin.x + (amber.quads[3].min.x + 2 * amber.reachEm) * draw.sizePx); x < extent.width; ++x)
      rest = std::max(rest, image.at(x, y)[0]);
  EXPECT_EQ(rest, 0.0f);
}

// More draws than one dispatch takes (32): they go in batches, each reading what the last wrote, and
// the order holds across batches: the last draw, over the first, wins.
TEST_F(TextPass, ManyDrawsGoInBatchesInOrder) {
  TextFrames frames(device());
  TextScene& scene = frames.scene();
  const text::TextLayout rose = scene.pass.layout(scene.cormorant, "ROSE", kSmallCaps);
  const VkExtent2D extent{800, 300};
  for (int i = 0; i < 40; ++i) {
    const glm::vec2 at(52.0f + float(i % 8) * 98.0f, 32.0f + float(i / 8) * 56.0f);
    scene.draws.push_back({&rose, at, false, 32.0f, {float(i + 1) / 64.0f, 0.5f, 0.25f, 1.0f}});
  }
  scene.draws.push_back(scene.draws[0]);
  scene.draws.back().color = {1.0f, 1.0f, 1.0f, 1.0f};
  const ImageRgba image = frames.render(extent);
  writeLook("many_draws", image);
  for (size_t i = 0; i < scene.draws.size(); ++i) {
    const text::TextDraw& draw = scene.draws[i];
    const glm::vec4 expected = i == 0 ? scene.draws.back().color : draw.color;
    int ink = 0;
    for (int y = 0; y < int(extent.height); ++y)
      for (int x = 0; x < int(extent.width); ++x)
        if (inkDistancePx(scene.pass.atlas(), draw, extent, x, y) > 0.9f) {
          ++ink;
          EXPECT_TRUE(near(image.at(uint32_t(x), uint32_t(y)), expected, 2e-3f)) << "draw " << i << " at " << x << "," << y;
        }
    EXPECT_GT(ink, 10) << "draw " << i;
  }
}

// Several draws in one frame, overlapping, one with a glow; a word laid out after construction is
// uploaded before it is drawn. Then the bloom scene's moment, for a look.
TEST_F(TextPass, SeveralDrawsAGlowAndAWordAddedLater) {
  TextFrames frames(device());
  TextScene& scene = frames.scene();
  const size_t before = scene.pass.atlas().glyphCount();
  const text::TextLayout later = scene.pass.layout(scene.italic, "Vitrine");
  EXPECT_GT(scene.pass.atlas().glyphCount(), before) << "new glyphs";
  const text::TextLayout chroma = scene.pass.layout(scene.italic, "CHROMA");
  const glm::vec4 charcoal{0.035f, 0.035f, 0.04f, 1.0f};
  text::TextDraw glowing{&chroma, {0.5f, 0.5f}, true, 120.0f, charcoal};
  glowing.glow = {glm::vec3(2.0f, 1.2f, 0.6f), 0.15f};
  text::TextDraw over{&later, {0.5f, 0.5f}, true, 40.0f, {0.2f, 0.8f, 1.0f, 1.0f}};
  scene.background = {0.02f, 0.02f, 0.03f, 1.0f};
  scene.draws = {glowing, over};
  const VkExtent2D extent{640, 240};
  const ImageRgba image = frames.render(extent);
  writeLook("glow_and_later_word", image);
  // The later word is drawn over CHROMA's ink: its colour wins where its own ink is.
  int laterInk = 0;
  for (int y = 0; y < int(extent.height); ++y)
    for (int x = 0; x < int(extent.width); ++x)
      if (inkDistancePx(scene.pass.atlas(), over, extent, x, y) > 1.5f) {
        ++laterInk;
        EXPECT_TRUE(near(image.at(uint32_t(x), uint32_t(y)), over.color, 2e-3f)) << x << "," << y;
      }
  EXPECT_GT(laterInk, 100);
  // The glow lights the background just outside CHROMA's letters and fades to nothing at its reach.
  int lit = 0;
  for (int y = 0; y < int(extent.height); ++y)
    for (int x = 0; x < int(extent.width); ++x) {
      const float d = inkDistancePx(scene.pass.atlas(), glowing, extent, x, y);
      if (inkDistancePx(scene.pass.atlas(), over, extent, x, y) > -3.0f) continue;
      const float red = image.at(uint32_t(x), uint32_t(y))[0];
      if (d < -2.0f && d > -6.0f) lit += red > 0.5f;
      if (d < -0.15f * 120.0f - 1.0f) {
        EXPECT_NEAR(red, scene.background.r, 1e-3f) << x << "," << y;
      }
    }
  EXPECT_GT(lit, 500);

  // The bloom scene's words: the colour names in Cormorant SC typing in, CHROMA blooming.
  const text::TextLayout amber = scene.pass.layout(scene.cormorant, "AMBER", kSmallCaps);
  const text::TextLayout rose = scene.pass.layout(scene.cormorant, "ROSE", kSmallCaps);
  const text::TextLayout crimson = scene.pass.layout(scene.cormorant, "CRIMSON", kSmallCaps);
  text::TextDraw big{&chroma, {0.5f, 0.62f}, true, 150.0f, charcoal};
  big.glow = {glm::vec3(1.6f, 0.9f, 0.5f), 0.12f};
  text::TextDraw typing{&crimson, {0.78f, 0.18f}, true, 34.0f, {0.8f, 0.1f, 0.12f, 1.0f}};
  typing.reveal = 0.6f;
  scene.background = {0.55f, 0.5f, 0.45f, 1.0f};
  scene.draws = {{&amber, {0.2f, 0.18f}, true, 34.0f, {1.0f, 0.55f, 0.1f, 1.0f}},
                 {&rose, {0.48f, 0.18f}, true, 34.0f, {0.9f, 0.35f, 0.45f, 1.0f}, 0.7f},
                 typing, big};
  writeLook("bloom_words", frames.render({800, 360}));
  // Large: the distance field is magnified five times.
  scene.background = {0.9f, 0.88f, 0.85f, 1.0f};
  scene.draws = {{&chroma, {0.5f, 0.5f}, true, 320.0f, charcoal}};
  writeLook("chroma_320px", frames.render({1400, 380}));
}

}  // namespace
}  // namespace vitrine::test
