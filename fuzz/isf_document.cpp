// ISF files (src/isf/isf_document.h): any bytes either read into a document or are refused with an
// IsfError naming a line inside the file; a document keeps its promises (at least one pass, names
// within bounds, sizes within bounds at any render size) and its uniform table is ordered and aligned.
#include "isf/isf_document.h"
#include "isf/isf_translate.h"

#include <algorithm>
#include <cstdint>
#include <string_view>

#include "support/require.h"

using namespace vitrine;
using vitrine::fuzz::require;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const int lines = isf::lineOf(text, text.size());
  isf::Document doc;
  try {
    doc = isf::parseDocument(text, "fuzz.fs");
  } catch (const isf::IsfError& e) {
    require(e.line >= 1 && e.line <= lines, "a refusal names a line outside the file");
    return 0;
  }
  require(!doc.passes.empty() && doc.passes.size() <= isf::kMaxPasses, "the passes are not 1..kMaxPasses");
  require(doc.inputs.size() <= isf::kMaxInputs, "more inputs than kMaxInputs");
  require(doc.glslFirstLine >= 1 && doc.glslFirstLine <= lines, "the GLSL starts outside the file");
  for (const auto& input : doc.inputs) require(input.line >= 1 && input.line <= lines, "an input's line is outside the file");
  for (const auto [w, h] : {std::pair{1, 1}, std::pair{1920, 1080}, std::pair{16384, 16384}}) {
    try {
      for (const auto& s : isf::passSizes(doc, w, h))
        require(s.width >= 1 && s.width <= isf::kMaxTargetSide && s.height >= 1 && s.height <= isf::kMaxTargetSide,
                "a pass size is outside 1..kMaxTargetSide");
    } catch (const isf::IsfError& e) {
      require(e.line >= 1 && e.line <= lines, "a size refusal names a line outside the file");
    }
  }
  for (size_t pass = 0; pass < doc.passes.size(); ++pass)
    for (const auto* target : doc.targets()) require(isf::readOf(doc, pass, target->target) != isf::PassRead::NotATarget, "a target is not one");
  const auto block = isf::frameBlock(doc);
  uint32_t end = 0;
  for (const auto& m : block.members) {
    require(m.offset >= end && m.offset % std::min(m.size, 16u) == 0, "block members overlap or are misaligned");
    end = m.offset + m.size;
  }
  require(block.size >= end && block.size % 16 == 0, "the block's size does not hold its members");
  return 0;
}
