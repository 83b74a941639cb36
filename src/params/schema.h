#pragma once
// One declaration per parameter. A scene keeps its values in a plain settings struct and declares each
// field once — key, label, help, group, type, range, default, flags — bound by member pointer. The
// command line (--set, --preset, --list-params), the panel, the settings file, presets and the
// benchmark's JSON all read this table; none of them has code for one parameter.
//
// Values cross every boundary as canonical text ("0.5", "on", "rk4", "32x32x8"), so one parse path,
// with one range check, serves the command line, the panel, files and remote control.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vitrine::params {

enum class Kind { Float, Int, Bool, Choice, Custom };

enum Flag : uint32_t {
  kLogarithmic = 1u << 0,     // the panel's slider is logarithmic
  kApplyOnRelease = 1u << 1,  // the panel applies the value when the widget is released, not per step
  kRebuilds = 1u << 2,        // changing it rebuilds GPU resources (implies apply-on-release in the panel)
  kTransient = 1u << 3,       // not saved in the settings file (camera pins, drags, debug state)
};

// One parameter: metadata plus type-erased access to its field inside a settings struct.
struct Param {
  std::string key;    // "noise_scale": the command line, files and remote control
  std::string label;  // "noise scale": the panel
  std::string help;   // one sentence: tooltip and --list-params
  std::string group;  // panel section; empty: the scene's first section
  Kind kind = Kind::Float;
  double min = 0.0, max = 0.0;       // Float and Int: inclusive range, the same for every front end
  std::vector<std::string> choices;  // Choice: the names, in the enum's order
  uint32_t flags = 0;
  std::string defaultText;  // canonical text of the default

  // Parse text, check it, store it into the struct; false with the reason in *error.
  std::function<bool(void* settings, std::string_view text, std::string* error)> parse;
  // The field's current value as canonical text.
  std::function<std::string(const void* settings)> format;
  // Float/Int: the value; Bool: 0/1; Choice: the index. Unused for Custom. For the panel's widgets.
  std::function<double(const void* settings)> number;

  bool has(Flag flag) const { return (flags & flag) != 0; }
  std::string typeName() const;  // "float 0.001..10", "int 1..9", "bool", "choice curl|bitangent", "custom"
};

// A named, partial set of key=value pairs a scene ships ("calm", "storm").
struct Preset {
  std::string name;
  std::string help;
  std::vector<std::pair<std::string, std::string>> values;
};

// The declarations of one scene, independent of any instance (so --list-params needs no GPU).
class Schema {
 public:
  const std::vector<Param>& params() const { return params_; }
  const std::vector<Preset>& presets() const { return presets_; }
  const Param* find(std::string_view key) const;
  const Preset* findPreset(std::string_view name) const;

  Schema& add(Param param);  // throws std::logic_error on a duplicate key or a default that fails its own parse
  Schema& preset(Preset preset);

 private:
  std::vector<Param> params_;
  std::vector<Preset> presets_;
};

// Builders: a field of struct S bound by member pointer. The default is the struct's own initial value
// (S must be default-constructible), so the default is written exactly once, in the struct.
struct Meta {
  std::string key, label, help, group;
  uint32_t flags = 0;
};

template <typename S> Param floatParam(Meta meta, float S::*field, double min, double max);
template <typename S> Param intParam(Meta meta, int S::*field, int min, int max);
template <typename S> Param boolParam(Meta meta, bool S::*field);
// An enum (or int) field whose values are 0..names.size()-1.
template <typename S, typename E> Param choiceParam(Meta meta, E S::*field, std::vector<std::string> names);
// Any field with its own parser and formatter (noodles' "grid" = "32x32x8").
template <typename S, typename T>
Param customParam(Meta meta, T S::*field, std::function<bool(std::string_view, T&, std::string*)> parse,
                  std::function<std::string(const T&)> format);

// A scene's live values: its schema and the struct the fields live in.
struct Bound {
  const Schema* schema = nullptr;
  void* settings = nullptr;
};

using KeyValues = std::vector<std::pair<std::string, std::string>>;

// Applies key=value pairs in order, then runs `check` once on the final values; on any failure every
// value is restored and the reason returned ("grid=4096: the strands would need 9.8 GiB ..."). Empty
// string: all applied. `check` may be null.
std::string apply(const Bound& bound, const KeyValues& values,
                  const std::function<std::string()>& check = nullptr);
KeyValues snapshot(const Bound& bound, bool includeTransient = true);  // every key with its canonical text
void resetToDefaults(const Bound& bound);                              // every parameter (no check needed)

// Canonical number formatting shared by every float parameter: shortest text that round-trips.
std::string formatFloat(double value);

}  // namespace vitrine::params

#include "params/schema_impl.h"  // the builder templates
