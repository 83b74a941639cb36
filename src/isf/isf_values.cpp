#include "isf/isf_values.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vitrine::isf {
namespace {

// The inputs a filter or a transition is handed frames for: no parameter names them.
bool isFrameInput(const Input& input) {
  return input.type == InputType::Image &&
         (input.name == "inputImage" || input.name == "startImage" || input.name == "endImage");
}

// A range that holds the default: a file that gives no MIN or MAX gets 0..1 widened to its default.
std::pair<float, float> rangeOf(const Input& input, int component) {
  const auto c = size_t(component);
  float lo = input.hasMin ? float(input.minValue[c]) : 0.0f;
  float hi = input.hasMax ? float(input.maxValue[c]) : 1.0f;
  if (lo > hi) std::swap(lo, hi);
  const float d = float(input.defaultValue[c]);
  if (!input.hasMin) lo = std::min(lo, d);
  if (!input.hasMax) hi = std::max(hi, d);
  return {lo, hi};
}

// The builder every ISF parameter goes through: like params' own builders (a refused value leaves the
// field alone, the default text comes from the defaults), for the element of Values::inputs at
// `index` rather than a member: a file's inputs are known only at run time.
params::Param inputParam(params::Meta meta, params::Kind kind, size_t index, const Values& defaults,
                         std::function<bool(std::string_view, InputValue&, std::string*)> parse,
                         std::function<std::string(const InputValue&)> format) {
  const auto at = [index](void* settings) -> InputValue* {
    auto& inputs = static_cast<Values*>(settings)->inputs;
    return index < inputs.size() ? &inputs[index] : nullptr;
  };
  return params::detail::bindAt<InputValue>(std::move(meta), kind, typeid(Values), at, defaults.inputs.at(index),
                                            std::move(parse), std::move(format));
}

std::function<double(const void*)> numberOf(size_t index, int component = 0) {
  return [index, component](const void* settings) {
    const auto& inputs = static_cast<const Values*>(settings)->inputs;
    return index < inputs.size() ? double(inputs[index].number[size_t(component)]) : 0.0;
  };
}

// A long's LABELS as choice names: words the command line and files can carry (what is not a letter,
// digit, '_', '-' or '.' becomes '_'), each once.
std::vector<std::string> choiceNames(const Input& input) {
  std::vector<std::string> names;
  for (size_t i = 0; i < input.values.size(); ++i) {
    std::string name = i < input.labels.size() ? input.labels[i] : std::to_string(input.values[i]);
    for (char& c : name)
      if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.'))
        c = '_';
    if (name.empty()) name = std::to_string(input.values[i]);
    const std::string base = name;
    for (int n = 2; std::find(names.begin(), names.end(), name) != names.end(); ++n) name = fmt::format("{}_{}", base, n);
    names.push_back(name);
  }
  return names;
}

}  // namespace

Values defaultValues(const Document& document) {
  Values values;
  for (const Input& input : document.inputs) {
    InputValue value;
    for (size_t c = 0; c < 4; ++c) value.number[c] = float(input.defaultValue[c]);
    if (input.type == InputType::Event) value.number[0] = 0.0f;  // an event has not fired
    if (input.type == InputType::Image && !isFrameInput(input)) value.file = "none";
    values.inputs.push_back(value);
  }
  return values;
}

int dragPoint(const Document& document) {
  int found = -1;
  for (size_t i = 0; i < document.inputs.size(); ++i) {
    if (document.inputs[i].type != InputType::Point2D) continue;
    if (found >= 0) return -1;
    found = int(i);
  }
  return found;
}

std::vector<std::string> eventNames(const Document& document) {
  std::vector<std::string> names;
  for (const Input& input : document.inputs)
    if (input.type == InputType::Event) names.push_back(input.name);
  return names;
}

params::Schema makeSchema(const Document& document, const std::vector<std::string>& skip) {
  const Values defaults = defaultValues(document);
  auto schema = params::Schema::forStruct<Values>(defaults);
  const int drag = dragPoint(document);
  const auto add = [&](params::Param param, const Input& input) {
    try {
      schema.add(std::move(param));
    } catch (const std::logic_error& e) {
      throw IsfError(document.file, input.line, e.what());
    }
  };
  for (size_t i = 0; i < document.inputs.size(); ++i) {
    const Input& input = document.inputs[i];
    if (std::find(skip.begin(), skip.end(), input.name) != skip.end()) continue;
    params::Meta meta{input.name, input.label.empty() ? input.name : input.label,
                      fmt::format("the file's {} input '{}'", typeName(input.type), input.name), "", 0};
    params::Param param;
    switch (input.type) {
      case InputType::Float: {
        // Plain variables, not a structured binding: clang 14 (the sanitizer and fuzz builds) cannot
        // capture a binding in a lambda.
        const std::pair<float, float> range = rangeOf(input, 0);
        const float lo = range.first, hi = range.second;
        param = inputParam(
            meta, params::Kind::Float, i, defaults,
            [lo, hi](std::string_view text, InputValue& v, std::string* e) { return params::parseFloatText(text, lo, hi, v.number[0], e); },
            [](const InputValue& v) { return params::formatFloat(v.number[0]); });
        param.min = lo;
        param.max = hi;
        param.number = numberOf(i);
        break;
      }
      case InputType::Long: {
        const std::vector<std::string> names = choiceNames(input);
        const std::vector<int> values = input.values;
        const auto indexOf = [values](const InputValue& v) {
          const auto it = std::find(values.begin(), values.end(), int(std::lround(v.number[0])));
          return it == values.end() ? 0 : int(it - values.begin());
        };
        param = inputParam(
            meta, params::Kind::Choice, i, defaults,
            [names, values](std::string_view text, InputValue& v, std::string* e) {
              for (size_t n = 0; n < names.size(); ++n)
                if (text == names[n]) return v.number[0] = float(values[n]), true;
              if (e) *e = "expected one of: " + fmt::format("{}", fmt::join(names, " "));
              return false;
            },
            [names, indexOf](const InputValue& v) { return names.empty() ? std::string() : names[size_t(indexOf(v))]; });
        param.choices = names;
        param.number = [i, indexOf](const void* settings) {
          const auto& inputs = static_cast<const Values*>(settings)->inputs;
          return i < inputs.size() ? double(indexOf(inputs[i])) : 0.0;
        };
        break;
      }
      case InputType::Bool:
        param = inputParam(
            meta, params::Kind::Bool, i, defaults,
            [](std::string_view text, InputValue& v, std::string* e) {
              bool on = false;
              if (!params::parseBoolText(text, on, e)) return false;
              return v.number[0] = on ? 1.0f : 0.0f, true;
            },
            [](const InputValue& v) { return std::string(v.number[0] != 0.0f ? "on" : "off"); });
        param.number = numberOf(i);
        break;
      case InputType::Color: {
        param = inputParam(
            meta, params::Kind::Colour, i, defaults,
            [](std::string_view text, InputValue& v, std::string* e) {
              glm::vec3 rgb;
              if (!params::parseColourText(text, rgb, e)) return false;
              v.number[0] = rgb.r, v.number[1] = rgb.g, v.number[2] = rgb.b;
              return true;
            },
            [](const InputValue& v) { return params::formatColour({v.number[0], v.number[1], v.number[2]}); });
        add(std::move(param), input);
        // Alpha as its own slider only where the file's default is not opaque: most colours are.
        const std::string alphaKey = input.name + "_alpha";
        if (input.defaultValue[3] != 1.0 && !document.findInput(alphaKey)) {
          params::Meta alpha{alphaKey, meta.label + " alpha", fmt::format("the alpha of the file's color input '{}'", input.name), "", 0};
          params::Param a = inputParam(
              alpha, params::Kind::Float, i, defaults,
              [](std::string_view text, InputValue& v, std::string* e) { return params::parseFloatText(text, 0.0f, 1.0f, v.number[3], e); },
              [](const InputValue& v) { return params::formatFloat(v.number[3]); });
          a.min = 0.0;
          a.max = 1.0;
          a.number = numberOf(i, 3);
          add(std::move(a), input);
        }
        continue;
      }
      case InputType::Point2D: {
        const std::pair<float, float> xRange = rangeOf(input, 0), yRange = rangeOf(input, 1);
        const float xlo = xRange.first, xhi = xRange.second, ylo = yRange.first, yhi = yRange.second;
        if (int(i) == drag) meta.flags |= params::kTransient;  // the drag's: a position, not a setting
        param = inputParam(
            meta, params::Kind::Custom, i, defaults,
            [=](std::string_view text, InputValue& v, std::string* e) {
              const size_t comma = text.find(',');
              if (comma == std::string_view::npos ||
                  !params::parseFloatText(text.substr(0, comma), xlo, xhi, v.number[0], nullptr) ||
                  !params::parseFloatText(text.substr(comma + 1), ylo, yhi, v.number[1], nullptr)) {
                if (e)
                  *e = fmt::format("expected x,y with x from {} to {} and y from {} to {}", params::formatFloat(xlo),
                                   params::formatFloat(xhi), params::formatFloat(ylo), params::formatFloat(yhi));
                return false;
              }
              return true;
            },
            [](const InputValue& v) {
              return fmt::format("{},{}", params::formatFloat(v.number[0]), params::formatFloat(v.number[1]));
            });
        break;
      }
      case InputType::Image: {
        if (isFrameInput(input)) continue;
        meta.flags |= params::kNamesFile;
        param = inputParam(
            meta, params::Kind::Custom, i, defaults,
            [](std::string_view text, InputValue& v, std::string* e) {
              if (text.empty()) {
                if (e) *e = "expected none or the path of a picture";
                return false;
              }
              return v.file = std::string(text), true;
            },
            [](const InputValue& v) { return v.file; });
        param.builtIns = {"none"};
        break;
      }
      case InputType::Event:
      case InputType::Audio:
      case InputType::AudioFFT: continue;
    }
    add(std::move(param), input);
  }
  return schema;
}

}  // namespace vitrine::isf
