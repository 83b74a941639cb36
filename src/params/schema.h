#pragma once
// One declaration per parameter. A scene keeps its values in a plain settings struct and declares each
// field once — key, label, help, group, type, range, default, flags — bound by member pointer. The
// command line (--set, --preset, --list-params), the panel, the settings file, presets and the
// benchmark's JSON all read this table; none of them has code for one parameter.
//
// Values cross every boundary as canonical text ("0.5", "on", "rk4", "32x32x8"), so one parse path,
// with one range check, serves the command line, the panel, files and remote control.
//
//   struct KifsSettings { int step = 9; Tier tier = Tier::High; float targetMs = 8.0f; };
//
//   const Schema& kifsSchema() {
//     static const Schema schema = [] {
//       auto s = Schema::forStruct<KifsSettings>();
//       s.add(intParam({.key = "step", .label = "stage", .help = "..."}, &KifsSettings::step, 1, 9));
//       s.add(choiceParam({.key = "tier", ...}, &KifsSettings::tier, {"auto", "high", "medium", "low"}));
//       s.preset({.name = "sketch", .help = "...", .values = {{"step", "3"}, {"tier", "low"}}});
//       return s;
//     }();
//     return schema;
//   }
#include <cstdint>
#include <glm/vec3.hpp>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <typeinfo>
#include <utility>
#include <vector>

namespace vitrine::params {

enum class Kind { Float, Int, Bool, Choice, Colour, Custom };

enum Flag : uint32_t {
  kLogarithmic = 1u << 0,     // the panel's slider is logarithmic
  kApplyOnRelease = 1u << 1,  // the panel applies the value when the widget is released, not per step
  kRebuilds = 1u << 2,        // changing it rebuilds GPU resources (implies apply-on-release in the panel)
  kTransient = 1u << 3,       // not saved in the settings file (camera pins, drags, debug state)
  kNamesFile = 1u << 4,       // the value may name a file on this computer: see fileParam
};

// One parameter: metadata plus type-erased access to its field inside a settings struct. Made by the
// builders below, never by hand.
struct Param {
  std::string key;    // "noise_scale": the command line, files and remote control
  std::string label;  // "noise scale": the panel
  std::string help;   // one sentence: tooltip and --list-params
  std::string group;  // panel section; empty: the scene's first section
  Kind kind = Kind::Float;
  double min = 0.0, max = 0.0;       // Float and Int: inclusive range, the same for every front end
  std::vector<std::string> choices;  // Choice: the names, in the enum's order
  std::vector<std::string> builtIns;  // kNamesFile: the values that name no file ("gradient", "photo_studio")
  uint32_t flags = 0;
  std::string defaultText;  // canonical text of the default

  // Parse text, check it, store it into the struct; false with the reason in *error (may be null).
  // A refused value leaves the field as it was.
  std::function<bool(void* settings, std::string_view text, std::string* error)> parse;
  // The field's current value as canonical text.
  std::function<std::string(const void* settings)> format;
  // Float/Int: the value; Bool: 0/1; Choice: the index. Empty for Colour and Custom. For the panel's widgets.
  std::function<double(const void* settings)> number;
  // Copies this field from one struct to another: exact save and restore, whatever the formatter.
  std::function<void(void* to, const void* from)> copy;
  const std::type_info* owner = nullptr;  // the settings struct the field belongs to

  bool has(Flag flag) const { return (flags & flag) != 0; }
  std::string typeName() const;  // "float 0.001..10", "int 1..9", "bool", "choice curl|bitangent", "custom"
};

// A named, partial set of key=value pairs a scene ships ("calm", "storm").
struct Preset {
  std::string name;
  std::string help;
  std::vector<std::pair<std::string, std::string>> values;
};

// The declarations of one scene, independent of any instance (so --list-params and the settings file
// need no GPU). Made for one settings struct by forStruct<S>(); declaration mistakes throw
// std::logic_error at start-up, so one test that builds every scene's schema catches them.
class Schema {
 public:
  template <typename S> static Schema forStruct();
  // For a struct whose defaults are known only at run time (an ISF file's inputs): `defaults` stands
  // in for S{} wherever the schema makes a default struct.
  template <typename S> static Schema forStruct(S defaults);

  const std::vector<Param>& params() const { return params_; }
  const std::vector<Preset>& presets() const { return presets_; }
  const Param* find(std::string_view key) const;
  const Preset* findPreset(std::string_view name) const;

  // Throws std::logic_error on a duplicate or malformed key, a field of another struct, or a default
  // that fails its own parse (out of range, an enum value without a name, a formatter that does not
  // round-trip).
  Schema& add(Param param);
  // Throws std::logic_error on a duplicate name, an unknown key or a value that does not parse. Declare
  // presets after the parameters they set.
  Schema& preset(Preset preset);
  // A mapping the scene plays with when live audio input is on (live/mapping.h's line, target
  // unqualified: "audio.bass=fold:1:1.12 release=0.3"). Checked by a unit test against the scene, since
  // the parameter layer knows no sources.
  Schema& audioMapping(std::string line) { return audioMappings_.push_back(std::move(line)), *this; }
  const std::vector<std::string>& audioMappings() const { return audioMappings_; }

  // A default-constructed settings struct (S{}): a scratch copy to validate values on, with no scene.
  std::shared_ptr<void> makeDefaults() const { return makeDefaults_(); }
  const std::type_info& settingsType() const { return *type_; }

 private:
  Schema(const std::type_info& type, std::function<std::shared_ptr<void>()> makeDefaults)
      : type_(&type), makeDefaults_(std::move(makeDefaults)) {}

  const std::type_info* type_;
  std::function<std::shared_ptr<void>()> makeDefaults_;
  std::vector<Param> params_;
  std::vector<Preset> presets_;
  std::vector<std::string> audioMappings_;
};

// Builders: a field of struct S bound by member pointer. The default is the struct's own initial value
// (S must be default-constructible), so the default is written exactly once, in the struct. S is
// deduced from the member pointer; for a field inherited from a base, name S explicitly
// (floatParam<Derived>(...)), or Schema::add refuses it as a field of another struct.
struct Meta {
  std::string key, label, help, group;
  uint32_t flags = 0;
};

template <typename S> Param floatParam(Meta meta, float S::*field, double min, double max);
template <typename S> Param intParam(Meta meta, int S::*field, int min, int max);
template <typename S> Param boolParam(Meta meta, bool S::*field);
// An enum (or integer, or bool) field whose values are 0..names.size()-1.
template <typename S, typename E> Param choiceParam(Meta meta, E S::*field, std::vector<std::string> names);
// A text field that is one of `builtIns` or the path of a file or folder on this computer (glass'
// background image, its panorama). Only the person at the computer may name a file: remote clients
// may set only the built-in names (remoteProblem), and are told nothing about any path.
template <typename S> Param fileParam(Meta meta, std::string S::*field, std::vector<std::string> builtIns);
// A colour as the panel's colour picker edits it and text spells it: "#rrggbb", sRGB-encoded values
// 0..1 in the field (a shader decodes them). Defaults are best written with hexColour(0xrrggbb).
template <typename S> Param colourParam(Meta meta, glm::vec3 S::*field);
// Any field with its own parser and formatter (noodles' "grid" = "32x32x8"). The parser may write
// `value` even when it fails: the field itself is only assigned on success.
template <typename S, typename T>
Param customParam(Meta meta, T S::*field, std::function<bool(std::string_view, T&, std::string*)> parse,
                  std::function<std::string(const T&)> format);

// A scene's live values: its schema and the struct the fields live in.
struct Bound {
  const Schema* schema = nullptr;
  void* settings = nullptr;
};
// Binds after checking that `settings` is the struct the schema was made for (std::logic_error if not).
template <typename S> Bound bindSettings(const Schema& schema, S& settings);

using KeyValues = std::vector<std::pair<std::string, std::string>>;
using Check = std::function<std::string()>;  // a cross-parameter check: empty when fine, else the reason

// Applies key=value pairs in order, then runs `check` once on the final values; on any failure every
// declared field is restored and the reason returned ("grid=4096: the strands would need 9.8 GiB ...").
// Empty string: all applied. `check` may be null. Since only the final values are judged, the order of
// the pairs never decides whether a batch is accepted. (Not named `apply`: called with a KeyValues,
// argument-dependent lookup would find std::apply.)
std::string applyValues(const Bound& bound, const KeyValues& values, const Check& check = nullptr);
KeyValues snapshot(const Bound& bound, bool includeTransient = true);  // every key with its canonical text
void resetToDefaults(const Bound& bound);  // every parameter; defaults pass any sane check
// One parameter back to its default, through applyValues: the other values may forbid it.
std::string resetToDefault(const Bound& bound, std::string_view key, const Check& check = nullptr);
// Applies a preset's values as one batch through applyValues; an unknown name returns the list of presets.
std::string applyPreset(const Bound& bound, std::string_view name, const Check& check = nullptr);

// Whether a remote client (OSC, the page's socket) may set `param` to `value`: empty when it may, else
// one refusal that is the same for every path a client could try, so it learns nothing of this
// computer's files. Every parameter but a kNamesFile one accepts what its parser accepts.
std::string remoteProblem(const Param& param, std::string_view value);
// The value as remote clients are shown it: a file's path is this computer's business ("a file").
std::string remoteView(const Param& param, std::string value);

// Canonical number formatting shared by every float parameter: the shortest text that reads back to
// the same float ("0.05", not "0.050000001").
std::string formatFloat(float value);

// The text rules every builder uses, for custom parsers that hold numbers (true on success; *error
// may be null). Strict: no sign '+', no spaces, no hex, no trailing characters, no NaN or infinity.
bool parseFloatText(std::string_view text, float min, float max, float& out, std::string* error);
bool parseIntText(std::string_view text, int min, int max, int& out, std::string* error);
bool parseBoolText(std::string_view text, bool& out, std::string* error);  // on/off, true/false, 1/0
bool parseColourText(std::string_view text, glm::vec3& out, std::string* error);  // "#rrggbb"
std::string formatColour(glm::vec3 colour);                                       // "#rrggbb", lower case
// 0xrrggbb as the field holds it: each channel / 255.
constexpr glm::vec3 hexColour(uint32_t rgb) {
  return {float((rgb >> 16) & 255u) / 255.0f, float((rgb >> 8) & 255u) / 255.0f, float(rgb & 255u) / 255.0f};
}

}  // namespace vitrine::params

#include "params/schema_impl.h"  // the builder templates
