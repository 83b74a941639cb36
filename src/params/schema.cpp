#include "params/schema.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace vitrine::params {
namespace {

std::string joined(const std::vector<std::string>& names, std::string_view separator) {
  return fmt::format("{}", fmt::join(names, separator));
}

std::vector<std::string> keysOf(const Schema& schema) {
  std::vector<std::string> keys;
  for (const Param& param : schema.params()) keys.push_back(param.key);
  return keys;
}

// Keys travel in "--set key=value", JSON objects and warnings that say "scene.key": plain words only.
bool isPlainKey(std::string_view key) {
  if (key.empty()) return false;
  for (const char c : key)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-'))
      return false;
  return true;
}

}  // namespace

std::string detail::choiceError(const std::vector<std::string>& names) {
  return "expected one of: " + joined(names, " ");
}

std::string formatFloat(float value) { return fmt::format("{}", value); }

bool parseFloatText(std::string_view text, float min, float max, float& out, std::string* error) {
  float value = 0.0f;
  // from_chars: no locale, no leading spaces or '+', no hex (chars_format::general); it does read
  // "nan" and "inf", which isfinite refuses, and reports 1e308 as out of range.
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || !(value >= min && value <= max)) {
    if (error) *error = fmt::format("expected a number from {} to {}", formatFloat(min), formatFloat(max));
    return false;
  }
  out = value;
  return true;
}

bool parseIntText(std::string_view text, int min, int max, int& out, std::string* error) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max) {
    if (error) *error = fmt::format("expected a whole number from {} to {}", min, max);
    return false;
  }
  out = value;
  return true;
}

bool parseBoolText(std::string_view text, bool& out, std::string* error) {
  if (text == "on" || text == "true" || text == "1") return out = true, true;
  if (text == "off" || text == "false" || text == "0") return out = false, true;
  if (error) *error = "expected on or off";
  return false;
}

bool parseColourText(std::string_view text, glm::vec3& out, std::string* error) {
  const auto hex = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
  };
  if (text.size() == 7 && text[0] == '#') {
    glm::vec3 colour;
    bool ok = true;
    for (int c = 0; c < 3; ++c) {
      const int hi = hex(text[size_t(1 + 2 * c)]), lo = hex(text[size_t(2 + 2 * c)]);
      ok = ok && hi >= 0 && lo >= 0;
      colour[c] = float(hi * 16 + lo) / 255.0f;
    }
    if (ok) return out = colour, true;
  }
  if (error) *error = "expected a colour as #rrggbb";
  return false;
}

std::string formatColour(glm::vec3 colour) {
  const auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  return fmt::format("#{:02x}{:02x}{:02x}", byte(colour.r), byte(colour.g), byte(colour.b));
}

std::string Param::typeName() const {
  switch (kind) {
    case Kind::Float: return fmt::format("float {}..{}", formatFloat(float(min)), formatFloat(float(max)));
    case Kind::Int: return fmt::format("int {}..{}", int(min), int(max));
    case Kind::Bool: return "bool";
    case Kind::Choice: return "choice " + joined(choices, "|");
    case Kind::Colour: return "colour #rrggbb";
    case Kind::Custom: return has(kNamesFile) ? "file or " + joined(builtIns, "|") : "custom";
  }
  return "?";
}

std::string remoteProblem(const Param& param, std::string_view value) {
  if (!param.has(kNamesFile) || std::find(param.builtIns.begin(), param.builtIns.end(), value) != param.builtIns.end())
    return {};
  // Judged before anything looks at the value: no path is ever opened, resolved or told apart.
  return fmt::format("{}: a remote client may choose only {}; files are chosen at the gallery", param.key,
                     joined(param.builtIns, ", "));
}

std::string remoteView(const Param& param, std::string value) {
  if (!remoteProblem(param, value).empty()) return "a file";
  return value;
}

const Param* Schema::find(std::string_view key) const {
  for (const Param& param : params_)
    if (param.key == key) return &param;
  return nullptr;
}

const Preset* Schema::findPreset(std::string_view name) const {
  for (const Preset& preset : presets_)
    if (preset.name == name) return &preset;
  return nullptr;
}

Schema& Schema::add(Param param) {
  const auto fail = [&](std::string_view why) {
    throw std::logic_error(fmt::format("parameter '{}': {}", param.key, why));
  };
  if (!isPlainKey(param.key)) fail("a key is a non-empty word of letters, digits, '_' or '-'");
  if (find(param.key)) fail("declared twice");
  if (!param.parse || !param.format || !param.copy || !param.owner) fail("made without a builder");
  if (*param.owner != *type_) fail(fmt::format("a field of {}, not of the schema's {}", param.owner->name(), type_->name()));
  if ((param.kind == Kind::Float || param.kind == Kind::Int) && !(param.min <= param.max)) fail("min above max");
  if (param.kind == Kind::Choice && param.choices.empty()) fail("a choice without names");

  // The default must be a value the parameter accepts, and its text must read back to itself, or a
  // saved default would be refused (or drift) on the next start.
  const auto scratch = makeDefaults();
  std::string why;
  if (!param.parse(scratch.get(), param.defaultText, &why))
    fail(fmt::format("the struct's default '{}' is refused: {}", param.defaultText, why));
  if (const std::string again = param.format(scratch.get()); again != param.defaultText)
    fail(fmt::format("the default '{}' reads back as '{}'", param.defaultText, again));

  params_.push_back(std::move(param));
  return *this;
}

Schema& Schema::preset(Preset preset) {
  const auto fail = [&](std::string_view why) {
    throw std::logic_error(fmt::format("preset '{}': {}", preset.name, why));
  };
  if (!isPlainKey(preset.name)) fail("a name is a non-empty word of letters, digits, '_' or '-'");
  if (findPreset(preset.name)) fail("declared twice");
  const auto scratch = makeDefaults();
  for (const auto& [key, text] : preset.values) {
    const Param* param = find(key);
    if (!param) fail(fmt::format("unknown parameter '{}' (declare presets after their parameters)", key));
    std::string why;
    if (!param->parse(scratch.get(), text, &why)) fail(fmt::format("{}={}: {}", key, text, why));
  }
  presets_.push_back(std::move(preset));
  return *this;
}

std::string applyValues(const Bound& bound, const KeyValues& values, const Check& check) {
  const Schema& schema = *bound.schema;
  // Save every declared field by copy, so a restore is exact whatever the formatters do.
  const auto saved = schema.makeDefaults();
  for (const Param& param : schema.params()) param.copy(saved.get(), bound.settings);
  const auto restore = [&] {
    for (const Param& param : schema.params()) param.copy(bound.settings, saved.get());
  };

  try {
    for (const auto& [key, text] : values) {
      const Param* param = schema.find(key);
      if (!param) {
        restore();
        return fmt::format("{}={}: unknown parameter; known: {}", key, text, joined(keysOf(schema), " "));
      }
      std::string why;
      if (!param->parse(bound.settings, text, &why)) {
        restore();
        return fmt::format("{}={}: {}", key, text, why);
      }
    }
    // Judged once, on the final values: "a=1000 b=0.01" must not fail half-way for an order that
    // passes through a forbidden combination.
    if (check) {
      if (std::string why = check(); !why.empty()) {
        restore();
        return why;
      }
    }
  } catch (...) {
    restore();
    throw;
  }
  return {};
}

KeyValues snapshot(const Bound& bound, bool includeTransient) {
  KeyValues values;
  for (const Param& param : bound.schema->params())
    if (includeTransient || !param.has(kTransient)) values.emplace_back(param.key, param.format(bound.settings));
  return values;
}

void resetToDefaults(const Bound& bound) {
  const auto defaults = bound.schema->makeDefaults();
  for (const Param& param : bound.schema->params()) param.copy(bound.settings, defaults.get());
}

std::string resetToDefault(const Bound& bound, std::string_view key, const Check& check) {
  const Param* param = bound.schema->find(key);
  if (!param) return fmt::format("{}: unknown parameter; known: {}", key, joined(keysOf(*bound.schema), " "));
  return applyValues(bound, {{param->key, param->defaultText}}, check);
}

std::string applyPreset(const Bound& bound, std::string_view name, const Check& check) {
  const Preset* preset = bound.schema->findPreset(name);
  if (!preset) {
    std::vector<std::string> names;
    for (const Preset& known : bound.schema->presets()) names.push_back(known.name);
    if (names.empty()) return fmt::format("unknown preset '{}': this scene has none", name);
    return fmt::format("unknown preset '{}'; expected one of: {}", name, joined(names, " "));
  }
  return applyValues(bound, preset->values, check);
}

}  // namespace vitrine::params
