#pragma once
// The builder templates of schema.h. Every builder goes through detail::bindField (and a run-time
// schema's through detail::bindAt, under it), so every kind gets the same guarantees: a refused value
// never touches the field, the default text comes from the defaults, and the owner type is recorded for
// Schema::add to check.
#include <fmt/format.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

namespace vitrine::params {

namespace detail {

// A parameter over the field `at` finds in a settings struct of type `owner` (null: the struct has no
// such field, and nothing is parsed, formatted or copied), whose default is `defaultValue`. A member
// field (bindField) and a field known only at run time (an ISF file's inputs, by index) share it. `at`
// only finds the field: formatting and copying never write through it.
template <typename T>
Param bindAt(Meta meta, Kind kind, const std::type_info& owner, std::function<T*(void*)> at, const T& defaultValue,
             std::function<bool(std::string_view, T&, std::string*)> parseValue,
             std::function<std::string(const T&)> formatValue) {
  static_assert(std::is_copy_assignable_v<T>, "applyValues saves and restores fields by copy");
  Param param;
  param.key = std::move(meta.key);
  param.label = std::move(meta.label);
  param.help = std::move(meta.help);
  param.group = std::move(meta.group);
  param.flags = meta.flags;
  param.kind = kind;
  param.owner = &owner;
  param.defaultText = formatValue(defaultValue);
  param.parse = [at, parseValue](void* settings, std::string_view text, std::string* error) {
    T* field = at(settings);
    if (!field) return false;
    // Parse into a copy: a parser that fails half-way must not leave a half-written field.
    T value = *field;
    std::string why;
    if (!parseValue(text, value, &why)) {
      if (error) *error = why;
      return false;
    }
    *field = std::move(value);
    return true;
  };
  param.format = [at, formatValue](const void* settings) {
    const T* field = at(const_cast<void*>(settings));
    return field ? formatValue(*field) : std::string();
  };
  param.copy = [at](void* to, const void* from) {
    T* target = at(to);
    const T* source = at(const_cast<void*>(from));
    if (target && source) *target = *source;
  };
  return param;
}

template <typename S, typename T>
Param bindField(Meta meta, Kind kind, T S::*field, std::function<bool(std::string_view, T&, std::string*)> parseValue,
                std::function<std::string(const T&)> formatValue) {
  static_assert(std::is_default_constructible_v<S>, "a settings struct needs defaults: S{} gives them");
  return bindAt<T>(
      std::move(meta), kind, typeid(S), [field](void* settings) { return &(static_cast<S*>(settings)->*field); },
      S{}.*field, std::move(parseValue), std::move(formatValue));
}

template <typename S, typename T> std::function<double(const void*)> numberOf(T S::*field) {
  return [field](const void* settings) { return double(static_cast<const S*>(settings)->*field); };
}

std::string choiceError(const std::vector<std::string>& names);

}  // namespace detail

template <typename S> Schema Schema::forStruct() {
  static_assert(std::is_default_constructible_v<S>, "a settings struct needs defaults: S{} gives them");
  return Schema(typeid(S), [] { return std::shared_ptr<void>(std::make_shared<S>()); });
}

template <typename S> Schema Schema::forStruct(S defaults) {
  static_assert(std::is_copy_constructible_v<S>, "the defaults are copied for every default struct");
  return Schema(typeid(S), [defaults = std::move(defaults)] { return std::shared_ptr<void>(std::make_shared<S>(defaults)); });
}

template <typename S> Bound bindSettings(const Schema& schema, S& settings) {
  if (schema.settingsType() != typeid(S))
    throw std::logic_error(fmt::format("a schema for {} bound to a {}", schema.settingsType().name(), typeid(S).name()));
  return Bound{&schema, &settings};
}

template <typename S> Param floatParam(Meta meta, float S::*field, double min, double max) {
  // The range is checked in float, as the field holds it: 0.0001 as a double is above 0.0001f.
  const float lo = float(min), hi = float(max);
  Param param = detail::bindField<S, float>(
      std::move(meta), Kind::Float, field,
      [lo, hi](std::string_view text, float& value, std::string* error) {
        return parseFloatText(text, lo, hi, value, error);
      },
      [](const float& value) { return formatFloat(value); });
  param.min = lo;
  param.max = hi;
  param.number = detail::numberOf(field);
  return param;
}

template <typename S> Param intParam(Meta meta, int S::*field, int min, int max) {
  Param param = detail::bindField<S, int>(
      std::move(meta), Kind::Int, field,
      [min, max](std::string_view text, int& value, std::string* error) {
        return parseIntText(text, min, max, value, error);
      },
      [](const int& value) { return fmt::to_string(value); });
  param.min = min;
  param.max = max;
  param.number = detail::numberOf(field);
  return param;
}

template <typename S> Param boolParam(Meta meta, bool S::*field) {
  Param param = detail::bindField<S, bool>(
      std::move(meta), Kind::Bool, field,
      [](std::string_view text, bool& value, std::string* error) { return parseBoolText(text, value, error); },
      [](const bool& value) { return std::string(value ? "on" : "off"); });
  param.number = detail::numberOf(field);
  return param;
}

template <typename S, typename E> Param choiceParam(Meta meta, E S::*field, std::vector<std::string> names) {
  static_assert(std::is_enum_v<E> || std::is_integral_v<E>, "a choice is an enum, integer or bool field");
  // Through the underlying integer, so a scoped enum and a bool read and write alike.
  using Index = typename std::conditional_t<std::is_enum_v<E>, std::underlying_type<E>, std::type_identity<E>>::type;
  Param param = detail::bindField<S, E>(
      std::move(meta), Kind::Choice, field,
      [names](std::string_view text, E& value, std::string* error) {
        for (size_t i = 0; i < names.size(); ++i)
          if (text == names[i]) return value = E(Index(i)), true;
        if (error) *error = detail::choiceError(names);
        return false;
      },
      [names](const E& value) {
        const auto index = int64_t(Index(value));
        // An out-of-range value still formats (as its number), so Schema::add can name the mistake.
        if (index < 0 || uint64_t(index) >= names.size()) return fmt::to_string(index);
        return names[size_t(index)];
      });
  param.choices = std::move(names);
  param.number = [field](const void* settings) { return double(Index(static_cast<const S*>(settings)->*field)); };
  return param;
}

template <typename S> Param colourParam(Meta meta, glm::vec3 S::*field) {
  return detail::bindField<S, glm::vec3>(
      std::move(meta), Kind::Colour, field,
      [](std::string_view text, glm::vec3& value, std::string* error) { return parseColourText(text, value, error); },
      [](const glm::vec3& value) { return formatColour(value); });
}

template <typename S, typename T>
Param customParam(Meta meta, T S::*field, std::function<bool(std::string_view, T&, std::string*)> parse,
                  std::function<std::string(const T&)> format) {
  return detail::bindField<S, T>(std::move(meta), Kind::Custom, field, std::move(parse), std::move(format));
}

template <typename S> Param fileParam(Meta meta, std::string S::*field, std::vector<std::string> builtIns) {
  meta.flags |= kNamesFile;
  Param param = detail::bindField<S, std::string>(
      std::move(meta), Kind::Custom, field,
      [](std::string_view text, std::string& value, std::string* error) {
        if (text.empty()) {
          if (error) *error = "expected a name or a path";
          return false;
        }
        value = std::string(text);
        return true;
      },
      [](const std::string& value) { return value; });
  param.builtIns = std::move(builtIns);
  return param;
}

}  // namespace vitrine::params
