#include "isf/isf_translate.h"

#include "core/printable.h"
#include "isf/isf_loops.h"
#include "isf/isf_names.h"
#include "isf/isf_tokens.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

namespace vitrine::isf {
namespace {

enum class Stage { Fragment, Vertex };

constexpr int kSourceGenerated = 0, kSourceFragment = 1, kSourceVertex = 2;

// GL 2.x / GLES names and their Vulkan GLSL 4.50 spellings. texture2D is a type in Vulkan GLSL, so a call
// to it must be renamed, not merely allowed.
const std::map<std::string_view, std::string_view> kRenames = {
    {"texture2D", "texture"},          {"texture2DProj", "textureProj"},   {"texture2DLod", "textureLod"},
    {"texture2DProjLod", "textureProjLod"}, {"texture2DLodEXT", "textureLod"}, {"texture2DGradEXT", "textureGrad"},
    {"textureCube", "texture"},        {"textureCubeLod", "textureLod"},   {"texture2DRect", "isf_texture2DRect"},
    {"main", "isf_main"},              {"gl_FragColor", "isf_FragColor"},   {"gl_FragData", "isf_FragData"},
    // ISF 1's names for what ISF 2 calls isf_*.
    {"vv_FragNormCoord", "isf_FragNormCoord"}, {"vv_vertShaderInit", "isf_vertShaderInit"},
};

std::string renamed(std::string_view word) {
  if (const auto it = kRenames.find(word); it != kRenames.end()) return std::string(it->second);
  if (reservedSinceGlsl1(word)) return "isf_r_" + std::string(word);
  return std::string(word);
}

int slotsOf(std::string_view type) {
  if (type == "mat2" || type == "mat2x2") return 2;
  if (type == "mat3" || type == "mat3x3") return 3;
  if (type == "mat4" || type == "mat4x4") return 4;
  return 1;
}

struct Varying {
  std::string name;
  int slots = 1;
  int line = 0;
};

// One stage's body rewritten: renames everywhere, locations on the global in/out declarations.
class Rewriter {
 public:
  Rewriter(std::string_view body, Stage stage, int firstLine, std::string file)
      : tokens_(tokenize(body)), facts_(loopFacts(tokens_)), stage_(stage), firstLine_(firstLine), file_(std::move(file)) {
    const std::optional<long long> worst = worstIterations(tokens_, facts_, "main", kLoopGuard + 1LL);
    withinBudget_ = worst && *worst <= kLoopGuard;
  }

  // With no locations given, only collects the varyings (vertex outputs, fragment inputs) and whether
  // the fragment stage declares its own outputs.
  std::string run(const std::map<std::string, int>* locations) {
    locations_ = locations;
    out_.clear();
    line_ = firstLine_;
    braces_ = parens_ = 0;
    fragmentOuts_ = 0;
    ownLayout_ = false;
    varyings_.clear();
    closeAfter_.clear();
    for (size_t i = 0; i < tokens_.size(); ++i) {
      const Token& t = tokens_[i];
      if (t.kind == Token::Kind::Identifier && braces_ == 0 && parens_ == 0 && isStorage(t.text)) {
        i = declaration(i);
        continue;
      }
      if (t.kind == Token::Kind::Identifier && t.text == "for")
        if (const std::optional<BoundedLoop> loop = boundedLoop(tokens_, i, facts_, kLoopGuard)) {
          // Left as written where every loop is fixed and all of them together fit the budget; else
          // charged once as it starts, so its count stays fixed for the compiler, in braces that keep
          // an `else` after it with the `if` it had.
          if (!withinBudget_) {
            out_ += fmt::format("{{ if (isf_enter({})) ", loop->trips);
            closeAfter_.push_back(loop->bodyEnd);
          }
          emit(t);
          continue;
        }
      if (t.kind == Token::Kind::Identifier && (t.text == "while" || t.text == "for")) {
        i = guardedLoop(i);
        continue;
      }
      // A declaration with a layout of its own keeps it, and gets no location from the rewrite.
      if (braces_ == 0 && t.kind == Token::Kind::Identifier && t.text == "layout") ownLayout_ = true;
      if (braces_ == 0 && t.kind == Token::Kind::Punct && (t.text == ";" || t.text == "}")) ownLayout_ = false;
      emit(t);
      if (const auto it = std::find(closeAfter_.begin(), closeAfter_.end(), i); it != closeAfter_.end()) {
        out_ += " }";
        closeAfter_.erase(it);
      }
    }
    return out_;
  }

  const std::vector<Varying>& varyings() const { return varyings_; }
  int fragmentOuts() const { return fragmentOuts_; }
  bool uses(std::string_view word) const {
    return std::any_of(tokens_.begin(), tokens_.end(),
                       [&](const Token& t) { return t.kind == Token::Kind::Identifier && t.text == word; });
  }

 private:
  static bool isStorage(std::string_view word) {
    return word == "varying" || word == "in" || word == "out" || word == "attribute" || word == "uniform";
  }
  static size_t newlines(std::string_view text) { return static_cast<size_t>(std::count(text.begin(), text.end(), '\n')); }

  [[noreturn]] void fail(const std::string& why) const { throw IsfError(file_, line_, why); }

  void emit(const Token& t) {
    switch (t.kind) {
      case Token::Kind::Identifier: out_ += renamed(t.text); break;
      case Token::Kind::Directive: out_ += directive(t.text); break;
      case Token::Kind::Punct:
        if (t.text == "{") ++braces_;
        if (t.text == "}") braces_ = std::max(0, braces_ - 1);
        if (t.text == "(") ++parens_;
        if (t.text == ")") parens_ = std::max(0, parens_ - 1);
        out_ += t.text;
        break;
      default: out_ += t.text;
    }
    line_ += static_cast<int>(newlines(t.text));
  }

  // #version goes (the preamble says 450); #extension lines of GL 2 / GLES go (what they enabled is core
  // in 4.50); other directives keep their words, with the identifiers in them renamed (#define T texture2D).
  static std::string directive(std::string_view text) {
    std::string_view word = text.substr(1);
    while (!word.empty() && (word.front() == ' ' || word.front() == '\t')) word.remove_prefix(1);
    if (word.substr(0, 7) == "version" || word.substr(0, 9) == "extension") return std::string(newlines(text), '\n');
    std::string out = "#";
    bool first = true;
    for (const Token& t : tokenize(text.substr(1))) {
      // The directive's own name (define, if, ifdef) is not renamed.
      out += (t.kind == Token::Kind::Identifier && !first) ? renamed(t.text) : std::string(t.text);
      if (t.kind == Token::Kind::Identifier) first = false;
    }
    return out;
  }

  // A loop's condition with the guard added: `while (c)` (also a do-while's) becomes
  // `while ((c) && isf_guard())`, `for (a; b; c)` becomes `for (a; (b) && isf_guard(); c)` and an empty
  // condition `isf_guard()`, so no loop runs past the invocation's bound (kLoopGuard). Emits the loop's
  // word and its condition; returns the index of the last token emitted.
  size_t guardedLoop(size_t start) {
    const bool isFor = tokens_[start].text == "for";
    emit(tokens_[start]);
    size_t i = nextWord(start + 1);
    if (i >= tokens_.size() || tokens_[i].text != "(") return start;  // not a loop: the compiler will say
    for (size_t k = start + 1; k <= i; ++k) emit(tokens_[k]);
    // The condition: from after '(' (or the init's ';') to the matching ')' (or the next ';').
    size_t from = i + 1, depth = 0;
    const auto scanTo = [&](size_t k, bool semicolon) {
      for (; k < tokens_.size(); ++k) {
        const std::string_view text = tokens_[k].text;
        if (tokens_[k].kind != Token::Kind::Punct) continue;
        if (depth == 0 && (semicolon ? text == ";" : text == ")")) return k;
        if (text == "(" || text == "[") ++depth;
        if ((text == ")" || text == "]") && depth > 0) --depth;
      }
      return tokens_.size();
    };
    if (isFor) {
      const size_t init = scanTo(from, true);
      if (init >= tokens_.size()) return i;
      for (size_t k = from; k <= init; ++k) emit(tokens_[k]);
      from = init + 1;
    }
    const size_t end = scanTo(from, isFor);
    if (end >= tokens_.size()) return i;
    const bool empty = std::all_of(tokens_.begin() + std::ptrdiff_t(from), tokens_.begin() + std::ptrdiff_t(end), spacing);
    if (!empty) out_ += "(";
    for (size_t k = from; k < end; ++k) emit(tokens_[k]);
    out_ += empty ? "isf_guard()" : ") && isf_guard()";
    return end - 1;
  }

  size_t nextWord(size_t i) const { return isf::nextWord(tokens_, i); }

  // A global declaration starting at the storage word tokens_[start]; returns the index of its last token.
  size_t declaration(size_t start) {
    const std::string_view storage = tokens_[start].text;
    if (storage == "uniform")
      fail("the shader declares a uniform; ISF declares one for each of INPUTS (and the images, passes and built-in "
           "values): declare it there, not in the code");
    const bool input = storage == "attribute" || (stage_ == Stage::Vertex && storage == "in") ||
                       (stage_ == Stage::Fragment && (storage == "in" || storage == "varying"));
    if (stage_ == Stage::Vertex && input)
      fail(fmt::format("the vertex shader declares a vertex input (\"{}\"); the host draws its quad from gl_VertexIndex "
                       "with no vertex buffer: call isf_vertShaderInit() and use isf_FragNormCoord", storage));
    const std::string_view spelled = storage == "varying" ? (input ? "in" : "out") : storage;
    if (ownLayout_) {
      out_ += spelled;
      if (stage_ == Stage::Fragment && !input) ++fragmentOuts_;
      return start;
    }
    // [precision] type name [ '[' N ']' ] (',' name [ '[' N ']' ])* ';'
    size_t i = nextWord(start + 1);
    std::string type;
    if (i < tokens_.size() && (tokens_[i].text == "lowp" || tokens_[i].text == "mediump" || tokens_[i].text == "highp")) {
      type = std::string(tokens_[i].text) + " ";
      i = nextWord(i + 1);
    }
    if (i >= tokens_.size() || tokens_[i].kind != Token::Kind::Identifier) {
      emit(tokens_[start]);  // not a declaration this rewrite understands (a block): kept as written
      return start;
    }
    const std::string_view typeWord = tokens_[i].text;
    type += renamed(typeWord);
    std::vector<std::pair<std::string, std::string>> names;  // name, array suffix
    for (;;) {
      i = nextWord(i + 1);
      if (i >= tokens_.size() || tokens_[i].kind != Token::Kind::Identifier) {
        emit(tokens_[start]);
        return start;
      }
      std::string name(tokens_[i].text), suffix;
      int count = 1;
      size_t j = nextWord(i + 1);
      if (j < tokens_.size() && tokens_[j].text == "[") {
        const size_t n = nextWord(j + 1);
        const size_t close = nextWord(n + 1);
        if (n >= tokens_.size() || tokens_[n].kind != Token::Kind::Number || close >= tokens_.size() || tokens_[close].text != "]") {
          emit(tokens_[start]);
          return start;
        }
        count = std::max(1, std::atoi(std::string(tokens_[n].text).c_str()));
        suffix = fmt::format("[{}]", tokens_[n].text);
        j = nextWord(close + 1);
      }
      names.emplace_back(name, suffix);
      if (stage_ == Stage::Vertex || input) varyings_.push_back({name, slotsOf(typeWord) * std::min(count, 64), line_});
      if (j >= tokens_.size()) {
        emit(tokens_[start]);
        return start;
      }
      if (tokens_[j].text == ";") {
        i = j;
        break;
      }
      if (tokens_[j].text != ",") {
        emit(tokens_[start]);
        return start;
      }
      i = j;
    }
    // Written again, one declaration per name, each with its location, and as many newlines as it took.
    int lines = 0;
    for (size_t k = start; k <= i; ++k) lines += static_cast<int>(newlines(tokens_[k].text));
    std::string text;
    for (const auto& [name, suffix] : names) {
      int location = 0;
      if (stage_ == Stage::Fragment && !input) {
        location = fragmentOuts_++;
      } else if (locations_) {
        const auto it = locations_->find(name);
        if (it == locations_->end())
          fail(fmt::format("the fragment shader reads \"{}\", which no vertex shader writes: a .vs file beside the "
                           "ISF file declares it as an output", printable(name)));
        location = it->second;
      }
      text += fmt::format("{}layout(location = {}) {} {} {}{};", text.empty() ? "" : " ", location, spelled, type,
                          renamed(name), suffix);
    }
    out_ += text + std::string(static_cast<size_t>(lines), '\n');
    line_ += lines;
    return i;
  }

  std::vector<Token> tokens_;
  LoopFacts facts_;
  bool withinBudget_ = false;  // worstIterations() of main() is at most kLoopGuard: no loop needs a charge
  Stage stage_;
  int firstLine_;
  std::string file_;
  const std::map<std::string, int>* locations_ = nullptr;
  std::string out_;
  int line_ = 0, braces_ = 0, parens_ = 0, fragmentOuts_ = 0;
  bool ownLayout_ = false;
  std::vector<Varying> varyings_;
  std::vector<size_t> closeAfter_;  // bounded loops' closing braces, each followed by the wrapper's
};

uint32_t alignUp(uint32_t x, uint32_t a) { return (x + a - 1) / a * a; }

// Which of gl_FragColor (isf_FragColor) and gl_FragData[0] (isf_FragData) is the fragment output at
// location 0; none when the code declares outputs of its own.
enum class FragmentOutput { Colour, Data, Own };

std::string declarations(const Document& doc, const Translation& t, Stage stage, FragmentOutput output) {
  std::string s;
  s += "// Generated from the ISF file's JSON: what ISF declares for the code below.\n";
  s += fmt::format("layout(std140, set = 0, binding = {}) uniform ISFFrame {{\n", kFrameBlockBinding);
  for (const BlockMember& m : t.frame.members) s += fmt::format("  layout(offset = {}) {} {};\n", m.offset, m.glslType, m.name);
  s += "};\n";
  // The invocation's loop budget (kLoopGuard), so a runaway shader cannot hang the GPU: a guarded loop's
  // condition calls isf_guard() each iteration; a loop whose trip count its text fixes (isf_loops.h) is
  // charged its whole count by isf_enter() as it starts, and runs whole or not at all.
  s += fmt::format("int isf_guardCount = 0;\nbool isf_guard() {{ return ++isf_guardCount <= {0}; }}\n"
                   "bool isf_enter(int trips) {{\n  if (isf_guardCount > {0}) return false;\n"
                   "  isf_guardCount += trips;\n  return isf_guardCount <= {0};\n}}\n", kLoopGuard);
  s += fmt::format("layout(push_constant) uniform ISFPass {{\n  layout(offset = {}) vec2 RENDERSIZE;\n"
                   "  layout(offset = {}) int PASSINDEX;\n}};\n", kRenderSizeOffset, kPassIndexOffset);
  for (const SamplerBinding& b : t.samplers) s += fmt::format("layout(set = 0, binding = {}) uniform sampler2D {};\n", b.binding, b.name);
  if (stage == Stage::Fragment) {
    s += "layout(location = 0) in vec2 isf_FragNormCoord;\n";
    s += output == FragmentOutput::Colour ? "layout(location = 0) out vec4 isf_FragColor;\n" : "vec4 isf_FragColor;\n";
    s += output == FragmentOutput::Data ? "layout(location = 0) out vec4 isf_FragData[1];\n" : "vec4 isf_FragData[1];\n";
  } else {
    s += "layout(location = 0) out vec2 isf_FragNormCoord;\n";
    // The quad's corners from the vertex index (a 4-vertex strip): GL's clip space, bottom-left first.
    s += "void isf_vertShaderInit() {\n"
         "  vec2 corner = vec2(float(gl_VertexIndex & 1), float((gl_VertexIndex >> 1) & 1));\n"
         "  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);\n"
         "  isf_FragNormCoord = corner;\n"
         "}\n";
  }
  s += "vec4 IMG_NORM_PIXEL(sampler2D image, vec2 normCoord) { return texture(image, normCoord); }\n"
       "vec4 IMG_PIXEL(sampler2D image, vec2 pixelCoord) { return texture(image, pixelCoord / vec2(textureSize(image, 0))); }\n"
       "vec4 IMG_THIS_NORM_PIXEL(sampler2D image) { return texture(image, isf_FragNormCoord); }\n"
       "vec4 IMG_NORM_THIS_PIXEL(sampler2D image) { return texture(image, isf_FragNormCoord); }\n"
       "vec4 IMG_THIS_PIXEL(sampler2D image) { return texture(image, isf_FragNormCoord); }\n"
       "vec2 IMG_SIZE(sampler2D image) { return vec2(textureSize(image, 0)); }\n"
       "vec4 isf_texture2DRect(sampler2D image, vec2 pixelCoord) { return IMG_PIXEL(image, pixelCoord); }\n";
  (void)doc;
  return s;
}

size_t lineCount(const std::string& s) { return static_cast<size_t>(std::count(s.begin(), s.end(), '\n')); }

// "#version 450", the declarations, the body under #line directives, and the entry point.
std::string assemble(const std::string& declared, const std::string& body, int firstLine, int source,
                     const std::string& entry) {
  std::string s = "#version 450\n" + declared;
  s += fmt::format("#line {} {}\n", firstLine, source);
  s += body;
  if (!body.empty() && body.back() != '\n') s += '\n';
  s += fmt::format("#line {} {}\n", lineCount(s) + 2, kSourceGenerated);
  s += entry;
  return s;
}

}  // namespace

BlockLayout frameBlock(const Document& doc) {
  BlockLayout layout;
  uint32_t offset = 0;
  auto add = [&](std::string name, std::string type, BlockMember::Source source, int input) {
    const uint32_t size = type == "vec4" ? 16 : type == "vec2" ? 8 : 4;
    offset = alignUp(offset, size);
    layout.members.push_back({std::move(name), std::move(type), offset, size, source, input});
    offset += size;
  };
  add("TIME", "float", BlockMember::Source::Time, -1);
  add("TIMEDELTA", "float", BlockMember::Source::TimeDelta, -1);
  add("FRAMEINDEX", "int", BlockMember::Source::FrameIndex, -1);
  add("DATE", "vec4", BlockMember::Source::Date, -1);
  for (size_t i = 0; i < doc.inputs.size(); ++i) {
    const Input& in = doc.inputs[i];
    const char* type = nullptr;
    switch (in.type) {
      case InputType::Event:
      case InputType::Bool: type = "bool"; break;
      case InputType::Long: type = "int"; break;
      case InputType::Float: type = "float"; break;
      case InputType::Point2D: type = "vec2"; break;
      case InputType::Color: type = "vec4"; break;
      default: continue;  // sampled: a binding, not a member
    }
    add(in.name, type, BlockMember::Source::Input, static_cast<int>(i));
  }
  layout.size = alignUp(offset, 16);
  return layout;
}

std::vector<SamplerBinding> samplerBindings(const Document& doc) {
  std::vector<SamplerBinding> out;
  uint32_t binding = kFrameBlockBinding + 1;
  for (const Input& in : doc.inputs)
    if (isSampled(in.type)) out.push_back({in.name, binding++, SamplerBinding::Source::Input});
  for (const ImportedImage& image : doc.imported) out.push_back({image.name, binding++, SamplerBinding::Source::Imported});
  for (const Pass* pass : doc.targets()) out.push_back({pass->target, binding++, SamplerBinding::Source::Target});
  return out;
}

Translation translate(const Document& doc, const std::optional<VertexFile>& vertex) {
  Translation t;
  t.frame = frameBlock(doc);
  t.samplers = samplerBindings(doc);
  t.sourceNames = {"<generated ISF preamble>", doc.file, vertex ? vertex->file : std::string("<generated vertex shader>")};

  Rewriter fragment(doc.glsl, Stage::Fragment, doc.glslFirstLine, doc.file);
  if (!fragment.uses("main")) throw IsfError(doc.file, doc.glslFirstLine, "the shader has no main()");
  fragment.run(nullptr);
  std::optional<Rewriter> vs;
  if (vertex) {
    vs.emplace(vertex->text, Stage::Vertex, 1, vertex->file);
    if (!vs->uses("main")) throw IsfError(vertex->file, 1, "the vertex shader has no main()");
    vs->run(nullptr);
  }

  // One location per varying name for both stages: the vertex shader's outputs in its order, from 1
  // (0 is isf_FragNormCoord). A fragment input no vertex output matches is refused by the rewrite.
  std::map<std::string, int> locations;
  int next = 1;
  if (vs)
    for (const Varying& v : vs->varyings()) {
      if (locations.count(v.name)) continue;
      if (next + v.slots > kMaxVaryingLocations)
        throw IsfError(vertex->file, v.line, fmt::format("the vertex shader passes more than {} vectors to the fragment "
                                                         "shader", kMaxVaryingLocations - 1));
      locations[v.name] = next;
      next += v.slots;
    }
  const std::string fragmentBody = fragment.run(&locations);
  const FragmentOutput output = fragment.fragmentOuts() > 0 ? FragmentOutput::Own
                                : fragment.uses("gl_FragData") && !fragment.uses("gl_FragColor") ? FragmentOutput::Data
                                                                                                 : FragmentOutput::Colour;
  t.fragment = assemble(declarations(doc, t, Stage::Fragment, output), fragmentBody, doc.glslFirstLine,
                        kSourceFragment, "void main() { isf_main(); }\n");
  // GL's clip-space depth runs -w..w, Vulkan's 0..w; x and y need nothing (see the header on images).
  const std::string vertexEntry = "void main() {\n  isf_main();\n  gl_Position.z = (gl_Position.z + gl_Position.w) * 0.5;\n}\n";
  if (vs) {
    t.vertex = assemble(declarations(doc, t, Stage::Vertex, FragmentOutput::Own), vs->run(&locations), 1, kSourceVertex, vertexEntry);
  } else {
    t.vertex = assemble(declarations(doc, t, Stage::Vertex, FragmentOutput::Own), "void isf_main() { isf_vertShaderInit(); }\n", 1,
                        kSourceGenerated, vertexEntry);
  }
  return t;
}

}  // namespace vitrine::isf
