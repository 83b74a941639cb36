#pragma once
// An ISF 2 file read into what it declares: its leading /* { JSON } */ comment (version, description,
// inputs, passes, imported images) and the GLSL after it, with the line each part starts on, so every
// complaint names the line of the author's file. Nothing here touches the GPU.
//
// Bounds (docs/ISF.md lists them): a file of at most kMaxFileBytes, refused before it is read whole;
// kMaxInputs inputs, kMaxPasses passes, kMaxImported imported images, kMaxLongValues entries in a long
// input's VALUES; names of at most 64 characters; every byte valid UTF-8 and none NUL.
#include "isf/isf_expression.h"

#include "core/error.h"

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::isf {

inline constexpr size_t kMaxFileBytes = size_t{1} << 20;  // 1 MiB: the largest files in the wild are ~40 KiB
inline constexpr size_t kMaxInputs = 64;
inline constexpr size_t kMaxPasses = 16;
inline constexpr size_t kMaxImported = 16;
inline constexpr size_t kMaxLongValues = 256;
inline constexpr int kMaxAudioSamples = 16384;
// Every pass target of one file together, at the sizes the render size gives (persistent ones counted
// twice: the host keeps the previous frame's copy to read while it writes the next).
inline constexpr uint64_t kMaxTargetBytes = uint64_t{1} << 30;
// The render size a file's pass sizes are checked at when it loads, with its inputs at their defaults.
inline constexpr int kReferenceSize[2] = {1920, 1080};

// A complaint about an ISF file: what() is "file:line: why", line being the line of the author's file.
struct IsfError : Error {
  IsfError(std::string file_, int line_, std::string why_);
  std::string file;
  int line = 0;
  std::string why;
};

enum class InputType { Event, Bool, Long, Float, Point2D, Color, Image, Audio, AudioFFT };
std::string_view typeName(InputType type);  // the TYPE string: "point2D"
bool isSampled(InputType type);              // image, audio, audioFFT: a sampler in the shader

struct Input {
  std::string name;
  std::string label;  // LABEL, or empty
  InputType type = InputType::Float;
  int line = 0;  // of its entry in the file
  // float: [0]; long: [0] (the value, not its index); bool and event: [0] as 0 or 1; point2D: [0..1];
  // color: [0..3] (RGBA). Absent MIN/MAX/IDENTITY leave has* false; an absent DEFAULT is the type's
  // zero (a float's MIN when it has one, a long's first VALUE, a color's opaque black).
  std::array<double, 4> defaultValue{0, 0, 0, 0}, minValue{0, 0, 0, 0}, maxValue{0, 0, 0, 0}, identity{0, 0, 0, 0};
  bool hasMin = false, hasMax = false, hasIdentity = false;
  std::vector<int> values;           // long: VALUES (or MIN..MAX when only those are given)
  std::vector<std::string> labels;   // long: LABELS, one per value (the values as text when absent)
  int audioSamples = 0;              // audio, audioFFT: MAX, the samples the shader wants; 0: as delivered
};

struct Pass {
  std::string target;  // empty: this pass draws the output
  bool persistent = false;
  bool floatTarget = false;
  std::optional<Expression> width, height;  // absent: the render size
  int line = 0;
};

struct ImportedImage {
  std::string name;
  std::filesystem::path path;  // as written (relative to the file's folder)
  int line = 0;
};

enum class Kind { Generator, Filter, Transition };
std::string_view kindName(Kind kind);

struct Document {
  std::string file;  // the name complaints give (the path as given)
  std::string isfVersion;  // ISFVSN, "1" when absent (the first version had no key)
  std::string vsn, description, credit;
  std::vector<std::string> categories;
  std::vector<Input> inputs;
  std::vector<Pass> passes;  // at least one: a file without PASSES has one pass to the output
  std::vector<ImportedImage> imported;
  Kind kind = Kind::Generator;
  std::string glsl;      // the shader after the JSON comment, from the character after "*/"
  int glslFirstLine = 1;  // the file's line that glsl's first character is on

  const Input* findInput(std::string_view name) const;
  // Every distinct pass target, in the order first named, with the first pass naming it.
  std::vector<const Pass*> targets() const;
};

// Reads and parses the file at `path` (refused before it is read if larger than kMaxFileBytes).
// Throws IsfError.
Document loadDocument(const std::filesystem::path& path);
// Parses the text of a file; `file` is the name complaints give. Throws IsfError.
Document parseDocument(std::string_view text, std::string file);

// What pass `pass` sees when it samples the buffer `target`: what an earlier pass of this frame drew,
// the last frame's (a PERSISTENT buffer, also in the pass that draws it), or transparent black (a
// buffer no earlier pass has drawn yet this frame). NotATarget: no pass draws `target`.
enum class PassRead { EarlierPass, PreviousFrame, Cleared, NotATarget };
PassRead readOf(const Document& document, size_t pass, std::string_view target);

// Throws IsfError at the line of the first byte that is NUL or breaks UTF-8 (an overlong form, a
// surrogate, past U+10FFFF): an ISF file, and the .vs beside it, is UTF-8 text.
void checkText(std::string_view text, const std::string& file);

// The line (1-based) of byte `offset` of `text`.
int lineOf(std::string_view text, size_t offset);

// Every pass's size at render size width x height with the inputs' values given by `value` (their
// defaults when it answers nullopt). Throws IsfError naming the pass's line when an expression gives
// no number or the targets together exceed kMaxTargetBytes; *notes receives a line for each size
// that was raised or lowered into bounds.
struct PassSize {
  int width = 0, height = 0;
};
std::vector<PassSize> passSizes(const Document& document, int width, int height,
                                const std::function<std::optional<double>(std::string_view)>& value = {},
                                std::vector<std::string>* notes = nullptr);

}  // namespace vitrine::isf
