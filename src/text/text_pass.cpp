#include "text/text_pass.h"

#include "core/error.h"
#include "shaders/text/text_blocks.h"

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <span>

namespace vitrine::text {
namespace {

constexpr float kEdgePx = 0.6f;   // half the anti-aliased edge, in target pixels, at every size
constexpr size_t kBatch = 32;     // draws per dispatch: one bit each in a tile's mask

template <typename T> std::span<const std::byte> bytes(const std::vector<T>& values) {
  return std::as_bytes(std::span(values));
}

glm::vec2 originPx(const TextDraw& draw, VkExtent2D extent) {
  glm::vec2 position = draw.position;
  if (draw.normalized) position *= glm::vec2(float(extent.width), float(extent.height));
  if (draw.anchor == Anchor::InkCentre) position -= draw.layout->inkCentre() * draw.sizePx;
  return position;
}

float glowPx(const TextDraw& draw) {
  return std::clamp(draw.glow.radiusEm, 0.0f, draw.layout->reachEm) * draw.sizePx;
}

float edgePx(const TextDraw& draw) {
  return std::min(kEdgePx + std::max(draw.softnessEm, 0.0f) * draw.sizePx,
                  std::max(draw.layout->reachEm * draw.sizePx, kEdgePx));
}

}  // namespace

TextPass::TextPass(const GpuContext& context, const std::vector<TextSource>& sources, const AtlasOptions& options)
    : device_(context.device), program_(context.programs, "text/text.comp"), atlas_(options) {
  // The CPU cuts the draws into tiles of one workgroup each: the shader's workgroup must be a tile.
  if (program_.localSize() != std::array<uint32_t, 3>{kTile, kTile, 1})
    throw Error(fmt::format("text/text.comp's workgroup is {}x{}x{}, not a {}x{} tile", program_.localSize()[0],
                            program_.localSize()[1], program_.localSize()[2], kTile, kTile));
  for (const TextSource& source : sources)
    if (source.font)
      for (const std::string& string : source.strings) atlas_.layout(*source.font, string, source.shaping);
  gpu::ImageDecl decl{"text atlas", VK_FORMAT_R8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT,
                      gpu::ImageSize::absolute(atlas_.width(), atlas_.height())};
  const auto texels = atlas_.texels();
  decl.initial.assign(reinterpret_cast<const std::byte*>(texels.data()),
                      reinterpret_cast<const std::byte*>(texels.data() + texels.size()));
  decl.initialUse = gpu::use::ComputeSample;
  image_ = context.resources.declare(std::move(decl));
  uploaded_ = atlas_.revision();
}

TextLayout TextPass::layout(const Font& font, std::string_view utf8, const Shaping& shaping) {
  return atlas_.layout(font, utf8, shaping);
}

PixelBox TextPass::bounds(const TextDraw& draw, VkExtent2D extent) {
  if (!draw.layout || draw.layout->empty() || !(draw.sizePx > 0.0f) || !std::isfinite(draw.sizePx)) return {};
  const glm::vec2 origin = originPx(draw, extent);
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y)) return {};
  const float margin = std::max(glowPx(draw), edgePx(draw)) + 1.0f;
  const glm::vec2 lo = glm::floor(origin + draw.layout->inkMin * draw.sizePx - margin);
  const glm::vec2 hi = glm::ceil(origin + draw.layout->inkMax * draw.sizePx + margin);
  auto clampTo = [](float value, uint32_t limit) { return int(std::clamp(value, 0.0f, float(limit))); };
  return {clampTo(lo.x, extent.width), clampTo(lo.y, extent.height), clampTo(hi.x, extent.width),
          clampTo(hi.y, extent.height)};
}

void TextPass::record(const FrameContext& frame, gpu::Image& target, const std::vector<TextDraw>& draws) {
  if (target.format() != VK_FORMAT_R16G16B16A16_SFLOAT || !(target.desc().usage & VK_IMAGE_USAGE_STORAGE_BIT))
    throw Error(fmt::format("Text is drawn into rgba16f storage images; {} is not one", target.name()));
  const VkExtent2D extent = target.extent2d();
  std::vector<shader::TextPassDraw> gpuDraws;
  std::vector<shader::TextPassGlyph> glyphs;
  std::vector<PixelBox> boxes;
  for (const TextDraw& draw : draws) {
    const PixelBox box = bounds(draw, extent);
    const float alpha = std::clamp(draw.color.a * draw.opacity, 0.0f, 1.0f);
    const float reveal = std::clamp(draw.reveal, 0.0f, 1.0f) * float(box.empty() ? 0 : draw.layout->quads.size());
    const bool glows = glowPx(draw) > 0.0f && draw.opacity > 0.0f && glm::any(glm::greaterThan(draw.glow.color,
                                                                                                glm::vec3(0.0f)));
    if (box.empty() || reveal <= 0.0f || (alpha <= 0.0f && !glows)) continue;
    const shader::TextPassDraw gpu{
        .color = glm::vec4(glm::vec3(draw.color), alpha),
        .glowColor = glows ? draw.glow.color * std::max(draw.opacity, 0.0f) : glm::vec3(0.0f),
        .glowRadius = glows ? glowPx(draw) : 0.0f,
        .origin = originPx(draw, extent),
        .pixelsPerEm = draw.sizePx,
        .revealed = reveal,
        .boxMin = {box.x0, box.y0},
        .boxMax = {box.x1, box.y1},
        .firstGlyph = uint32_t(glyphs.size()),
        .glyphCount = uint32_t(draw.layout->quads.size()),
        .halfEdge = edgePx(draw),
        .unused = 0.0f};
    for (const GlyphQuad& quad : draw.layout->quads) glyphs.push_back({quad.min, quad.max, quad.uvMin, quad.uvMax});
    gpuDraws.push_back(gpu);
    boxes.push_back(box);
  }
  if (gpuDraws.empty()) return;

  const auto pass = frame.pass("text");
  gpu::Image& atlas = frame.image(image_);
  if (uploaded_ != atlas_.revision()) {  // glyphs laid out after construction
    const auto texels = atlas_.texels();
    gpu::uploadImage(frame.cmd, frame.stream, atlas, std::as_bytes(texels), gpu::use::ComputeSample);
    uploaded_ = atlas_.revision();
  }
  frame.transition(atlas, gpu::use::ComputeSample);
  const gpu::StreamSlice drawSlice = frame.stream.write(bytes(gpuDraws));
  const gpu::StreamSlice glyphSlice = frame.stream.write(bytes(glyphs));
  const gpu::Bindings bindings =
      gpu::Bindings()
          .storageImage("target", target.desc().mips > 1 ? target.mipView(0) : target.view())  // a chain: level 0
          .sampledImage("atlas", atlas.view(),
                        device_.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                        gpu::use::ComputeSample.layout)
          .storageBuffer("Draws", drawSlice.buffer, drawSlice.offset, drawSlice.size)
          .storageBuffer("Glyphs", glyphSlice.buffer, glyphSlice.offset, glyphSlice.size);
  const float sdfEdge = 128.0f / 255.0f, emPerUnit = 255.0f / 128.0f * atlas_.reachEm();
  const uint32_t maxGroups = device_.limits().maxComputeWorkGroupCount[0];

  // Each batch of up to 32 draws: the tiles their boxes touch, each with a mask of the draws over it,
  // so every pixel is read and written once per batch.
  for (size_t first = 0; first < gpuDraws.size(); first += kBatch) {
    std::vector<glm::uvec2> marks;  // tile (x | y << 16), draw bit
    for (size_t i = first; i < std::min(first + kBatch, gpuDraws.size()); ++i) {
      const PixelBox& box = boxes[i];
      for (uint32_t ty = uint32_t(box.y0) / kTile; ty <= uint32_t(box.y1 - 1) / kTile; ++ty)
        for (uint32_t tx = uint32_t(box.x0) / kTile; tx <= uint32_t(box.x1 - 1) / kTile; ++tx)
          marks.push_back({tx | (ty << 16), 1u << (i - first)});
    }
    std::sort(marks.begin(), marks.end(), [](const glm::uvec2& a, const glm::uvec2& b) { return a.x < b.x; });
    std::vector<shader::TextPassTile> tiles;
    for (const glm::uvec2& mark : marks) {
      if (!tiles.empty() && tiles.back().position == mark.x)
        tiles.back().drawMask |= mark.y;
      else
        tiles.push_back({.position = mark.x, .drawMask = mark.y, .firstDraw = uint32_t(first)});
    }
    const gpu::StreamSlice tileSlice = frame.stream.write(bytes(tiles));
    gpu::Bindings batch = bindings;
    batch.storageBuffer("Tiles", tileSlice.buffer, tileSlice.offset, tileSlice.size);
    for (uint32_t start = 0; start < tiles.size(); start += maxGroups) {
      const uint32_t count = std::min<uint32_t>(maxGroups, uint32_t(tiles.size()) - start);
      frame.transition(target, gpu::use::ComputeReadWrite);  // after whatever wrote it, or the last batch
      program_.bind(frame.cmd);
      program_.push(frame.cmd, batch);
      program_.constants(frame.cmd, shader::TextPassPush{start, count, sdfEdge, emPerUnit});
      program_.dispatchGroups(frame.cmd, {count, 1, 1});  // one workgroup a tile
    }
  }
}

}  // namespace vitrine::text
