#include "isf/isf_document.h"

#include "core/bounded_file.h"
#include "core/printable.h"
#include "isf/isf_json_place.h"
#include "isf/isf_names.h"
#include "isf/isf_tokens.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

namespace vitrine::isf {

IsfError::IsfError(std::string file_, int line_, std::string why_)
    : Error(fmt::format("{}:{}: {}", file_, line_, why_)), file(std::move(file_)), line(line_), why(std::move(why_)) {}

namespace {

using json = nlohmann::json;

constexpr int kMaxJsonDepth = 32;  // the deepest real header nests 4 levels

using Lookup = std::function<std::optional<double>(std::string_view)>;
// passSizes; `strict` (on load, at the defaults) refuses a size out of bounds instead of clamping it.
std::vector<PassSize> computeSizes(const Document& doc, int width, int height, const Lookup& value,
                                   std::vector<std::string>* notes, bool strict);

struct TypeEntry {
  std::string_view name;
  InputType type;
};
constexpr TypeEntry kTypes[] = {
    {"event", InputType::Event}, {"bool", InputType::Bool},       {"long", InputType::Long},
    {"float", InputType::Float}, {"point2D", InputType::Point2D}, {"color", InputType::Color},
    {"image", InputType::Image}, {"audio", InputType::Audio},     {"audioFFT", InputType::AudioFFT},
};

// The first byte that breaks UTF-8 (or is NUL), or npos. Overlong forms, surrogates and code points past
// U+10FFFF are refused, as a strict decoder does.
size_t firstInvalidUtf8(std::string_view s) {
  size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c == 0) return i;
    if (c < 0x80) {
      ++i;
      continue;
    }
    size_t length = 0;
    uint32_t code = 0;
    if ((c & 0xE0) == 0xC0) length = 2, code = c & 0x1F;
    else if ((c & 0xF0) == 0xE0) length = 3, code = c & 0x0F;
    else if ((c & 0xF8) == 0xF0) length = 4, code = c & 0x07;
    else return i;
    if (i + length > s.size()) return i;
    for (size_t k = 1; k < length; ++k) {
      const auto next = static_cast<unsigned char>(s[i + k]);
      if ((next & 0xC0) != 0x80) return i;
      code = (code << 6) | (next & 0x3F);
    }
    const uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return i;
    i += length;
  }
  return std::string_view::npos;
}

// Where the nesting of arrays and objects in JSON text (strings skipped) first passes kMaxJsonDepth,
// or npos: refused there before the parser builds anything.
size_t tooDeep(std::string_view s) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return std::string_view::npos;
}

class Reader {
 public:
  Reader(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  Document read() {
    Document doc;
    doc.file = file_;
    checkText(text_, file_);
    size_t start = 0;
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") start = 3;  // a byte-order mark some editors write
    while (start < text_.size() && std::isspace(static_cast<unsigned char>(text_[start]))) ++start;
    if (text_.substr(start, 2) != "/*")
      fail(lineOf(text_, start), "an ISF file starts with a /* comment holding its JSON description; this one does not");
    const size_t close = text_.find("*/", start + 2);
    if (close == std::string_view::npos) fail(lineOf(text_, start), "the JSON comment opened here is never closed with */");
    jsonStart_ = start + 2;
    json_ = text_.substr(jsonStart_, close - jsonStart_);
    doc.glsl = std::string(text_.substr(close + 2));
    doc.glslFirstLine = lineOf(text_, close);

    if (const size_t deep = tooDeep(json_); deep != std::string_view::npos)
      fail(lineOf(text_, jsonStart_ + deep), fmt::format("the JSON nests deeper than {} levels", kMaxJsonDepth));
    json top;
    try {
      top = json::parse(json_);
    } catch (const json::parse_error& e) {
      fail(lineOf(text_, jsonStart_ + std::min(e.byte > 0 ? e.byte - 1 : 0, json_.size())),
           "the JSON description does not parse: " + jsonReason(e.what()));
    } catch (const json::exception& e) {
      // A number too large for a double ("number overflow parsing '1E999'"): the line of the number it quotes.
      const std::string what = e.what();
      const size_t quote = what.find('\''), unquote = what.rfind('\'');
      const size_t at = quote < unquote ? json_.find(what.substr(quote + 1, unquote - quote - 1)) : std::string_view::npos;
      fail(lineOf(text_, jsonStart_ + (at == std::string_view::npos ? 0 : at)),
           "the JSON description does not parse: " + jsonReason(what));
    }
    if (!top.is_object()) fail(lineOf(text_, jsonStart_), "the JSON description is not an object ({ ... })");

    doc.isfVersion = versionText(top, "ISFVSN", "1");
    doc.vsn = versionText(top, "VSN", "");
    doc.description = optionalString(top, "DESCRIPTION");
    doc.credit = optionalString(top, "CREDIT");
    if (top.contains("CATEGORIES")) {
      const auto& categories = top["CATEGORIES"];
      if (!categories.is_array()) fail(at({"CATEGORIES"}), "CATEGORIES is not an array of strings");
      for (size_t i = 0; i < categories.size(); ++i) {
        if (!categories[i].is_string()) fail(at({"CATEGORIES", i}), "a CATEGORIES entry is not a string");
        doc.categories.push_back(categories[i].get<std::string>());
      }
    }
    if (top.contains("PERSISTENT_BUFFERS"))
      fail(at({"PERSISTENT_BUFFERS"}), "PERSISTENT_BUFFERS is ISF 1's; ISF 2 says PERSISTENT in the pass that draws the buffer");
    readInputs(top, doc);
    readImported(top, doc);
    readPasses(top, doc);
    doc.kind = kindOf(doc);
    checkReads(doc);
    return doc;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& why) const { throw IsfError(file_, line, why); }

  int at(const JsonPath& path) const { return lineOf(text_, jsonStart_ + jsonPlace(json_, path)); }

  static std::string jsonReason(std::string what) {
    // nlohmann's "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ...":
    // its line and column count from the comment's start, so only the words after them are kept.
    if (const size_t column = what.find(", column "); column != std::string::npos)
      if (const size_t colon = what.find(": ", column); colon != std::string::npos) return what.substr(colon + 2);
    if (const size_t bracket = what.find("] "); bracket != std::string::npos) return what.substr(bracket + 2);
    return what;
  }

  std::string versionText(const json& top, const char* key, const char* absent) const {
    if (!top.contains(key)) return absent;
    const auto& value = top[key];
    if (value.is_string()) return printable(value.get<std::string>());
    if (value.is_number()) return fmt::format("{}", value.dump());
    fail(at({key}), fmt::format("{} is not a version string (\"2.0\")", key));
  }

  std::string optionalString(const json& top, const char* key) const {
    if (!top.contains(key)) return {};
    if (!top[key].is_string()) fail(at({key}), fmt::format("{} is not a string", key));
    return top[key].get<std::string>();
  }

  double number(const json& value, const JsonPath& path, std::string_view what) const {
    if (value.is_boolean()) return value.get<bool>() ? 1.0 : 0.0;
    if (!value.is_number()) fail(at(path), fmt::format("{} is not a number", what));
    const double x = value.get<double>();
    if (!std::isfinite(x) || std::fabs(x) > 1e30) fail(at(path), fmt::format("{} is out of any useful range", what));
    return x;
  }

  // A vector value: a JSON array of `size` numbers (a color may give 3, then alpha is 1).
  std::array<double, 4> vector(const json& value, const JsonPath& path, size_t size, std::string_view what) const {
    std::array<double, 4> out{0, 0, 0, 1};
    const bool colour = size == 4;
    if (!value.is_array() || value.size() > size || value.size() < (colour ? 3 : size))
      fail(at(path), fmt::format("{} is not an array of {} numbers", what, colour ? "3 or 4" : std::to_string(size)));
    for (size_t i = 0; i < value.size(); ++i) {
      JsonPath element = path;
      element.push_back(i);
      out[i] = number(value[i], element, what);
    }
    return out;
  }

  void checkName(const std::string& name, int line, std::string_view what) {
    if (const std::string why = whyNotAName(name); !why.empty())
      fail(line, fmt::format("the {} name \"{}\" {}", what, printable(name), why));
    if (!names_.insert(name).second) fail(line, fmt::format("the name \"{}\" is given twice: each input, pass target "
                                                            "and imported image needs its own", name));
  }

  void readInputs(const json& top, Document& doc) {
    if (!top.contains("INPUTS")) return;
    const auto& inputs = top["INPUTS"];
    if (!inputs.is_array()) fail(at({"INPUTS"}), "INPUTS is not an array of objects");
    if (inputs.size() > kMaxInputs)
      fail(at({"INPUTS", kMaxInputs}), fmt::format("INPUTS has {} entries; at most {} are read", inputs.size(), kMaxInputs));
    for (size_t i = 0; i < inputs.size(); ++i) doc.inputs.push_back(readInput(inputs[i], i));
  }

  Input readInput(const json& entry, size_t index) {
    Input in;
    in.line = at({"INPUTS", index});
    if (!entry.is_object()) fail(in.line, "an INPUTS entry is not an object");
    auto path = [&](const char* key) { return JsonPath{"INPUTS", index, key}; };
    if (!entry.contains("NAME") || !entry["NAME"].is_string()) fail(in.line, "an input has no NAME string");
    in.name = entry["NAME"].get<std::string>();
    checkName(in.name, at(path("NAME")), "input");
    if (!entry.contains("TYPE") || !entry["TYPE"].is_string())
      fail(in.line, fmt::format("the input \"{}\" has no TYPE string", in.name));
    const std::string type = entry["TYPE"].get<std::string>();
    const auto* known = std::find_if(std::begin(kTypes), std::end(kTypes), [&](const TypeEntry& t) { return t.name == type; });
    if (known == std::end(kTypes))
      fail(at(path("TYPE")), fmt::format("the input \"{}\" has the TYPE \"{}\", which ISF 2 does not define (event, bool, "
                                         "long, float, point2D, color, image, audio, audioFFT)", in.name, printable(type)));
    in.type = known->type;
    if (entry.contains("LABEL")) {
      if (!entry["LABEL"].is_string()) fail(at(path("LABEL")), "LABEL is not a string");
      in.label = entry["LABEL"].get<std::string>();
    }
    const std::string what = fmt::format("the input \"{}\"'s", in.name);
    auto scalar = [&](const char* key, double& out) {
      if (!entry.contains(key)) return false;
      out = number(entry[key], path(key), fmt::format("{} {}", what, key));
      return true;
    };
    auto vec = [&](const char* key, size_t size, std::array<double, 4>& out) {
      if (!entry.contains(key)) return false;
      out = vector(entry[key], path(key), size, fmt::format("{} {}", what, key));
      return true;
    };
    switch (in.type) {
      case InputType::Float:
        in.hasMin = scalar("MIN", in.minValue[0]);
        in.hasMax = scalar("MAX", in.maxValue[0]);
        in.hasIdentity = scalar("IDENTITY", in.identity[0]);
        if (!scalar("DEFAULT", in.defaultValue[0]) && in.hasMin) in.defaultValue[0] = in.minValue[0];
        if (in.hasMin && in.hasMax && in.minValue[0] > in.maxValue[0])
          fail(at(path("MIN")), fmt::format("the input \"{}\"'s MIN is above its MAX", in.name));
        if (in.hasMin) in.defaultValue[0] = std::max(in.defaultValue[0], in.minValue[0]);
        if (in.hasMax) in.defaultValue[0] = std::min(in.defaultValue[0], in.maxValue[0]);
        break;
      case InputType::Bool:
      case InputType::Event:
        if (scalar("DEFAULT", in.defaultValue[0])) in.defaultValue[0] = in.defaultValue[0] != 0.0 ? 1.0 : 0.0;
        if (in.type == InputType::Event) in.defaultValue[0] = 0.0;  // an event fires only when asked
        break;
      case InputType::Long: readLong(entry, index, in); break;
      case InputType::Point2D:
        in.hasMin = vec("MIN", 2, in.minValue);
        in.hasMax = vec("MAX", 2, in.maxValue);
        in.hasIdentity = vec("IDENTITY", 2, in.identity);
        vec("DEFAULT", 2, in.defaultValue);
        break;
      case InputType::Color:
        in.defaultValue = {0, 0, 0, 1};
        in.hasMin = vec("MIN", 4, in.minValue);
        in.hasMax = vec("MAX", 4, in.maxValue);
        in.hasIdentity = vec("IDENTITY", 4, in.identity);
        vec("DEFAULT", 4, in.defaultValue);
        break;
      case InputType::Audio:
      case InputType::AudioFFT:
        if (double samples = 0; scalar("MAX", samples)) {
          if (samples < 1 || samples > kMaxAudioSamples || samples != std::floor(samples))
            fail(at(path("MAX")), fmt::format("the input \"{}\"'s MAX ({:g}) is not a number of samples from 1 to {}",
                                              in.name, samples, kMaxAudioSamples));
          in.audioSamples = static_cast<int>(samples);
        }
        break;
      case InputType::Image: break;
    }
    return in;
  }

  void readLong(const json& entry, size_t index, Input& in) {
    auto path = [&](const char* key) { return JsonPath{"INPUTS", index, key}; };
    auto integer = [&](const json& value, const JsonPath& where, std::string_view what) {
      const double x = number(value, where, what);
      if (x != std::floor(x) || std::fabs(x) > 2147483647.0) fail(at(where), fmt::format("{} is not an integer", what));
      return static_cast<int>(x);
    };
    if (entry.contains("VALUES")) {
      const auto& values = entry["VALUES"];
      if (!values.is_array() || values.empty()) fail(at(path("VALUES")), fmt::format("the input \"{}\"'s VALUES is not an array of integers", in.name));
      if (values.size() > kMaxLongValues)
        fail(at(path("VALUES")), fmt::format("the input \"{}\" has {} VALUES; at most {} are read", in.name, values.size(), kMaxLongValues));
      for (size_t i = 0; i < values.size(); ++i)
        in.values.push_back(integer(values[i], {"INPUTS", index, "VALUES", i}, fmt::format("a VALUES entry of \"{}\"", in.name)));
    } else {
      double lo = 0, hi = 0;
      const bool hasMin = entry.contains("MIN"), hasMax = entry.contains("MAX");
      if (!hasMin || !hasMax) fail(in.line, fmt::format("the long input \"{}\" has neither VALUES nor MIN and MAX", in.name));
      lo = integer(entry["MIN"], path("MIN"), "MIN");
      hi = integer(entry["MAX"], path("MAX"), "MAX");
      if (hi < lo || hi - lo + 1 > kMaxLongValues)
        fail(at(path("MIN")), fmt::format("the long input \"{}\" spans {:g}..{:g}: it must hold from 1 to {} values",
                                          in.name, lo, hi, kMaxLongValues));
      for (double v = lo; v <= hi; ++v) in.values.push_back(static_cast<int>(v));
    }
    if (entry.contains("LABELS")) {
      const auto& labels = entry["LABELS"];
      if (!labels.is_array() || labels.size() != in.values.size())
        fail(at(path("LABELS")), fmt::format("the input \"{}\"'s LABELS is not an array of {} strings, one per value",
                                             in.name, in.values.size()));
      for (size_t i = 0; i < labels.size(); ++i) {
        if (!labels[i].is_string()) fail(at({"INPUTS", index, "LABELS", i}), "a LABELS entry is not a string");
        in.labels.push_back(labels[i].get<std::string>());
      }
    } else {
      for (const int v : in.values) in.labels.push_back(std::to_string(v));
    }
    in.defaultValue[0] = in.values.front();
    if (entry.contains("DEFAULT")) {
      const int d = integer(entry["DEFAULT"], path("DEFAULT"), "DEFAULT");
      if (std::find(in.values.begin(), in.values.end(), d) != in.values.end()) in.defaultValue[0] = d;
    }
    if (entry.contains("IDENTITY")) in.hasIdentity = true, in.identity[0] = integer(entry["IDENTITY"], path("IDENTITY"), "IDENTITY");
  }

  void readImported(const json& top, Document& doc) {
    if (!top.contains("IMPORTED")) return;
    const auto& imported = top["IMPORTED"];
    // The specification's form is an object of name -> {PATH}; many files write an array of {NAME, PATH}.
    if (!imported.is_object() && !imported.is_array()) fail(at({"IMPORTED"}), "IMPORTED is not an object of images");
    if (imported.size() > kMaxImported)
      fail(at({"IMPORTED"}), fmt::format("IMPORTED names {} images; at most {} are read", imported.size(), kMaxImported));
    size_t index = 0;
    for (auto it = imported.begin(); it != imported.end(); ++it, ++index) {
      JsonPath place = imported.is_object() ? JsonPath{"IMPORTED", it.key()} : JsonPath{"IMPORTED", index};
      ImportedImage image;
      image.line = at(place);
      const json& entry = it.value();
      if (!entry.is_object()) fail(image.line, "an IMPORTED entry is not an object with a PATH");
      if (imported.is_object()) {
        image.name = it.key();
      } else {
        if (!entry.contains("NAME") || !entry["NAME"].is_string()) fail(image.line, "an IMPORTED entry has no NAME string");
        image.name = entry["NAME"].get<std::string>();
      }
      checkName(image.name, image.line, "imported image");
      if (!entry.contains("PATH") || !entry["PATH"].is_string() || entry["PATH"].get<std::string>().empty())
        fail(image.line, fmt::format("the imported image \"{}\" has no PATH string", image.name));
      image.path = entry["PATH"].get<std::string>();
      doc.imported.push_back(std::move(image));
    }
  }

  bool flag(const json& pass, size_t index, const char* key) const {
    if (!pass.contains(key)) return false;
    const auto& value = pass[key];
    if (value.is_boolean()) return value.get<bool>();
    if (value.is_number()) return value.get<double>() > 0;
    // Some files write "true" / "1" as strings.
    if (value.is_string()) return value == "true" || value == "1" || value == "YES";
    fail(at({"PASSES", index, key}), fmt::format("{} is not true or false", key));
  }

  void readPasses(const json& top, Document& doc) {
    const json* passes = top.contains("PASSES") ? &top["PASSES"] : nullptr;
    if (passes && !passes->is_array()) fail(at({"PASSES"}), "PASSES is not an array of objects");
    if (!passes || passes->empty()) {
      Pass single;
      single.line = doc.glslFirstLine;
      doc.passes.push_back(std::move(single));
      return;
    }
    if (passes->size() > kMaxPasses)
      fail(at({"PASSES", kMaxPasses}), fmt::format("PASSES has {} entries; at most {} are drawn", passes->size(), kMaxPasses));
    std::set<std::string> ownNames;  // a target drawn by several passes is one buffer
    for (size_t i = 0; i < passes->size(); ++i) {
      const json& entry = (*passes)[i];
      Pass pass;
      pass.line = at({"PASSES", i});
      if (!entry.is_object()) fail(pass.line, "a PASSES entry is not an object");
      if (entry.contains("TARGET")) {
        if (!entry["TARGET"].is_string()) fail(at({"PASSES", i, "TARGET"}), "TARGET is not a string");
        pass.target = entry["TARGET"].get<std::string>();
      }
      pass.persistent = flag(entry, i, "PERSISTENT");
      pass.floatTarget = flag(entry, i, "FLOAT");
      if ((pass.persistent || pass.floatTarget) && pass.target.empty())
        fail(pass.line, "a pass is PERSISTENT or FLOAT but has no TARGET buffer to be so");
      for (const char* key : {"WIDTH", "HEIGHT"}) {
        if (!entry.contains(key)) continue;
        const int line = at({"PASSES", i, key});
        std::string text;
        if (entry[key].is_string()) text = entry[key].get<std::string>();
        else if (entry[key].is_number()) text = entry[key].dump();
        else fail(line, fmt::format("{} is not an expression string (\"$WIDTH/2\")", key));
        try {
          Expression expression = Expression::parse(text);
          for (const auto& name : expression.variables()) checkVariable(doc, name, line);
          (std::string_view(key) == "WIDTH" ? pass.width : pass.height) = std::move(expression);
        } catch (const IsfError&) {
          throw;
        } catch (const Error& e) {
          fail(line, fmt::format("the pass's {}: {}", key, e.what()));
        }
      }
      if (!pass.target.empty()) {
        if (ownNames.count(pass.target)) {
          const Pass& first = *std::find_if(doc.passes.begin(), doc.passes.end(), [&](const Pass& p) { return p.target == pass.target; });
          auto text = [](const std::optional<Expression>& e) { return e ? e->text() : std::string("$"); };
          if (first.persistent != pass.persistent || first.floatTarget != pass.floatTarget ||
              text(first.width) != text(pass.width) || text(first.height) != text(pass.height))
            fail(pass.line, fmt::format("this pass draws \"{}\" as the pass on line {} does, but with another PERSISTENT, "
                                        "FLOAT, WIDTH or HEIGHT: one buffer has one of each", pass.target, first.line));
        } else {
          checkName(pass.target, pass.line, "pass target");
          ownNames.insert(pass.target);
        }
      }
      doc.passes.push_back(std::move(pass));
    }
    // The sizes at a common render size with the defaults, so an absurd constant is refused on load.
    computeSizes(doc, kReferenceSize[0], kReferenceSize[1], {}, nullptr, true);
  }

  void checkVariable(const Document& doc, const std::string& name, int line) const {
    if (name == "WIDTH" || name == "HEIGHT") return;
    const Input* input = doc.findInput(name);
    if (!input)
      fail(line, fmt::format("the size names ${}, which is not an input (a size reads $WIDTH, $HEIGHT and number inputs)", name));
    if (input->type != InputType::Float && input->type != InputType::Long && input->type != InputType::Bool &&
        input->type != InputType::Event)
      fail(line, fmt::format("the size names ${}, a {} input; a size reads only float, long, bool and event inputs", name,
                             typeName(input->type)));
  }

  static Kind kindOf(const Document& doc) {
    auto image = [&](const char* name) {
      const Input* input = doc.findInput(name);
      return input && input->type == InputType::Image;
    };
    const Input* progress = doc.findInput("progress");
    if (image("startImage") && image("endImage") && progress && progress->type == InputType::Float) return Kind::Transition;
    if (image("inputImage")) return Kind::Filter;
    return Kind::Generator;
  }

  // A buffer the shader reads must be readable in some pass: drawn by an earlier pass of the frame, or
  // kept from the last frame (PERSISTENT). A pass never reads what it draws itself (Vulkan cannot
  // sample an image while rendering to it), so a non-persistent buffer that only its own pass, or only
  // later passes, could read is a loop the file cannot mean.
  static void checkReads(const Document& doc) {
    std::set<std::string_view> read;
    for (const Token& token : tokenize(doc.glsl))
      if (token.kind == Token::Kind::Identifier) read.insert(token.text);
    for (const Pass* target : doc.targets()) {
      if (target->persistent || !read.count(target->target)) continue;
      bool readable = false;
      for (size_t k = 0; k < doc.passes.size(); ++k)
        if (readOf(doc, k, target->target) == PassRead::EarlierPass) readable = true;
      if (!readable)
        throw IsfError(doc.file, target->line,
                       fmt::format("the shader reads \"{}\", but no pass can: the pass that draws it cannot read it while "
                                   "drawing it, and no later pass reads it; make it PERSISTENT to read the last frame's",
                                   target->target));
    }
  }

  std::string_view text_;
  std::string file_;
  size_t jsonStart_ = 0;
  std::string_view json_;
  std::set<std::string> names_;
};

std::vector<PassSize> computeSizes(const Document& doc, int width, int height, const Lookup& value,
                                   std::vector<std::string>* notes, bool strict) {
  auto lookup = [&](std::string_view name) -> std::optional<double> {
    if (name == "WIDTH") return width;
    if (name == "HEIGHT") return height;
    if (value)
      if (auto given = value(name)) return given;
    if (const Input* input = doc.findInput(name)) return input->defaultValue[0];
    return std::nullopt;
  };
  std::vector<PassSize> sizes;
  uint64_t bytes = 0;
  std::set<std::string_view> counted;
  for (const Pass& pass : doc.passes) {
    PassSize size{width, height};
    for (const auto& [expression, out, key] : {std::tuple{&pass.width, &size.width, "WIDTH"}, std::tuple{&pass.height, &size.height, "HEIGHT"}}) {
      if (!*expression) continue;
      const auto result = (*expression)->evaluate(lookup);
      std::string why;
      const auto pixels = result ? sizeFromValue(*result, &why) : std::nullopt;
      if (!result) why = "it names a value that is not there";
      if (!pixels || (strict && !why.empty()))
        throw IsfError(doc.file, pass.line, fmt::format("the pass's {} \"{}\" at {}x{}: {}", key,
                                                        printable((*expression)->text()), width, height,
                                                        strict && pixels ? fmt::format("it gives {:g} pixels, outside 1..{}", *result, kMaxTargetSide) : why));
      if (!why.empty() && notes) notes->push_back(fmt::format("{}:{}: {}", doc.file, pass.line, why));
      *out = *pixels;
    }
    sizes.push_back(size);
    if (!pass.target.empty() && counted.insert(pass.target).second)
      bytes += uint64_t(size.width) * uint64_t(size.height) * (pass.floatTarget ? 16u : 8u) * (pass.persistent ? 2u : 1u);
    if (bytes > kMaxTargetBytes)
      throw IsfError(doc.file, pass.line, fmt::format("the pass buffers take {} at {}x{}; at most {} are given to one file",
                                                      bytesInWords(bytes), width, height, bytesInWords(kMaxTargetBytes)));
  }
  return sizes;
}

}  // namespace

std::string_view typeName(InputType type) {
  for (const auto& entry : kTypes)
    if (entry.type == type) return entry.name;
  return "?";
}

bool isSampled(InputType type) {
  return type == InputType::Image || type == InputType::Audio || type == InputType::AudioFFT;
}

std::string_view kindName(Kind kind) {
  switch (kind) {
    case Kind::Generator: return "generator";
    case Kind::Filter: return "filter";
    case Kind::Transition: return "transition";
  }
  return "?";
}

const Input* Document::findInput(std::string_view name) const {
  for (const Input& input : inputs)
    if (input.name == name) return &input;
  return nullptr;
}

std::vector<const Pass*> Document::targets() const {
  std::vector<const Pass*> out;
  for (const Pass& pass : passes)
    if (!pass.target.empty() && std::none_of(out.begin(), out.end(), [&](const Pass* p) { return p->target == pass.target; }))
      out.push_back(&pass);
  return out;
}

PassRead readOf(const Document& doc, size_t pass, std::string_view target) {
  const Pass* declared = nullptr;
  for (const Pass& p : doc.passes)
    if (p.target == target) declared = declared ? declared : &p;
  if (!declared || pass >= doc.passes.size()) return PassRead::NotATarget;
  if (doc.passes[pass].target == target) return declared->persistent ? PassRead::PreviousFrame : PassRead::Cleared;
  for (size_t j = 0; j < pass; ++j)
    if (doc.passes[j].target == target) return PassRead::EarlierPass;
  return declared->persistent ? PassRead::PreviousFrame : PassRead::Cleared;
}

void checkText(std::string_view text, const std::string& file) {
  const size_t bad = firstInvalidUtf8(text);
  if (bad == std::string_view::npos) return;
  throw IsfError(file, lineOf(text, bad),
                 text[bad] == '\0' ? "a NUL byte: an ISF file is text"
                                   : fmt::format("byte 0x{:02X} is not valid UTF-8: an ISF file is UTF-8 text",
                                                 static_cast<unsigned char>(text[bad])));
}

int lineOf(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

Document parseDocument(std::string_view text, std::string file) {
  if (text.size() > kMaxFileBytes)
    throw IsfError(file, 1, fmt::format("the file is {}; an ISF file may be at most {}", bytesInWords(text.size()),
                                        bytesInWords(kMaxFileBytes)));
  return Reader(text, std::move(file)).read();
}

Document loadDocument(const std::filesystem::path& path) {
  std::string text;
  try {
    text = readBoundedFile(path, kMaxFileBytes);
  } catch (const FileRefused& refused) {
    throw IsfError(path.string(), 1, fmt::format("cannot be read: {} (an ISF file may be at most {})", refused.why,
                                                 bytesInWords(kMaxFileBytes)));
  }
  return parseDocument(text, path.string());
}

std::vector<PassSize> passSizes(const Document& document, int width, int height, const Lookup& value,
                                std::vector<std::string>* notes) {
  return computeSizes(document, width, height, value, notes, false);
}

}  // namespace vitrine::isf
