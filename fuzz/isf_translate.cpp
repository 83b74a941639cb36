// The GLSL translation of ISF code (src/isf/isf_translate.h), under a fixed header with every kind of
// input, an imported image and passes: the input is the fragment code, then optionally a NUL byte and
// the vertex code. Any code is either translated or refused with an IsfError at a line of its file;
// a translation keeps every line of the author's code where it was (the #line mapping depends on it).
#include "isf/isf_document.h"
#include "isf/isf_tokens.h"
#include "isf/isf_translate.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "support/require.h"

using namespace vitrine;
using vitrine::fuzz::require;

namespace {

constexpr std::string_view kHeader = R"(/*{
  "ISFVSN": "2",
  "INPUTS": [
    {"NAME": "inputImage", "TYPE": "image"}, {"NAME": "level", "TYPE": "float"}, {"NAME": "on", "TYPE": "bool"},
    {"NAME": "hit", "TYPE": "event"}, {"NAME": "mode", "TYPE": "long", "VALUES": [0, 1]},
    {"NAME": "spot", "TYPE": "point2D"}, {"NAME": "tint", "TYPE": "color"},
    {"NAME": "wave", "TYPE": "audio"}, {"NAME": "fft", "TYPE": "audioFFT", "MAX": 16}
  ],
  "IMPORTED": {"stamp": {"PATH": "stamp.png"}},
  "PASSES": [{"TARGET": "trail", "PERSISTENT": true, "WIDTH": "$WIDTH/2"}, {}]
}*/)";

size_t newlines(std::string_view s) { return static_cast<size_t>(std::count(s.begin(), s.end(), '\n')); }

// The text between "#line FIRST SOURCE\n" and the next "#line": the author's code as translated.
void checkLinesKept(const std::string& translated, int first, int source, std::string_view original) {
  // Code that writes #line itself, or continues a line with a backslash, is not measured here.
  if (original.find("#line") != std::string_view::npos || original.find("\\\n") != std::string_view::npos) return;
  const std::string marker = "#line " + std::to_string(first) + " " + std::to_string(source) + "\n";
  const size_t start = translated.find(marker);
  require(start != std::string::npos, "the translation has no #line for the author's code");
  const size_t from = start + marker.size();
  const size_t end = translated.find("#line ", from);
  require(end != std::string::npos, "the translation has no #line after the author's code");
  const size_t kept = newlines(std::string_view(translated).substr(from, end - from));
  // The code as translated is followed by a newline of the translation's own unless it is empty or
  // already ends with one: it does when the author's does, or when its last line is a #version or
  // #extension line, which the translation drops.
  const size_t had = newlines(original);
  const bool endsWithNewline = !original.empty() && original.back() == '\n';
  bool lastDropped = false;
  if (const auto tokens = isf::tokenize(original); !endsWithNewline && !tokens.empty() && tokens.back().kind == isf::Token::Kind::Directive) {
    std::string_view word = tokens.back().text.substr(1);
    while (!word.empty() && (word.front() == ' ' || word.front() == '\t')) word.remove_prefix(1);
    lastDropped = word.substr(0, 7) == "version" || word.substr(0, 9) == "extension";
  }
  const bool empty = original.empty() || (lastDropped && had == 0);
  const bool translatedEndsWithNewline = endsWithNewline || (lastDropped && had > 0);
  require(kept == had + (!empty && !translatedEndsWithNewline ? 1 : 0), "the translation moved the author's lines");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const size_t split = input.find('\0');
  const std::string_view fragment = input.substr(0, split);
  std::optional<isf::VertexFile> vertex;
  if (split != std::string_view::npos) vertex = isf::VertexFile{std::string(input.substr(split + 1)), "fuzz.vs"};
  isf::Document doc;
  try {
    doc = isf::parseDocument(std::string(kHeader) + std::string(fragment), "fuzz.fs");
  } catch (const isf::IsfError&) {
    return 0;  // the document's own target covers its refusals
  }
  try {
    const isf::Translation t = isf::translate(doc, vertex);
    checkLinesKept(t.fragment, doc.glslFirstLine, 1, doc.glsl);
    if (vertex) checkLinesKept(t.vertex, 1, 2, vertex->text);
    require(t.fragment.rfind("#version 450\n", 0) == 0 && t.vertex.rfind("#version 450\n", 0) == 0,
            "a translation does not start with #version 450");
  } catch (const isf::IsfError& e) {
    const bool inVertex = e.file == "fuzz.vs";
    require(inVertex || e.file == "fuzz.fs", "a refusal names another file");
    require(e.line >= 1, "a refusal names a line before the first");
    if (inVertex) require(e.line <= 1 + static_cast<int>(newlines(vertex->text)), "a refusal names a line past the .vs file's end");
    else require(e.line <= doc.glslFirstLine + static_cast<int>(newlines(doc.glsl)), "a refusal names a line past the file's end");
  }
  return 0;
}
