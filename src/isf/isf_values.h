#pragma once
// The live values of an ISF file's inputs, as its shader receives them, and the parameter schema that
// sets them (docs/ISF.md, "How inputs map onto Vitrine's parameters"): a file's INPUTS become a
// params::Schema built at run time, so the command line, presets, the panel, the settings file, remote
// control, live mappings, films and the bench work on any file with no code for it. No GPU here.
#include "isf/isf_document.h"
#include "params/schema.h"

#include <array>
#include <string>
#include <vector>

namespace vitrine::isf {

struct InputValue {
  // float: [0]; long: [0] the VALUE (not its index); bool and event: [0] 0 or 1; point2D: [0..1];
  // color: [0..3], RGBA as the file means them (display values, not linear light).
  std::array<float, 4> number{0, 0, 0, 0};
  std::string file;  // image inputs: the picture named ("" or "none": none)
};

// The settings struct of every ISF schema: one value per entry of Document::inputs, in that order.
struct Values {
  std::vector<InputValue> inputs;
};

// Every input at its DEFAULT.
Values defaultValues(const Document& document);

// The parameters of a file's inputs (keys are the inputs' NAMEs): float -> Float (MIN..MAX, 0..1 when
// absent), long -> Choice of its LABELS, bool -> Bool, color -> Colour plus "NAME_alpha" when the
// default's alpha is not 1, point2D -> Custom "x,y" within MIN..MAX (kTransient when it is the file's
// only one: the cursor's drag sets it), image (not a filter's or transition's own) -> a file parameter
// with the built-in "none". event, audio and audioFFT make no parameter; inputs named in `skip` (the
// progress a transition's host drives) neither. Throws IsfError naming the input's line when a name
// cannot be a key.
params::Schema makeSchema(const Document& document, const std::vector<std::string>& skip = {});

// The one point2D input the cursor's drag moves (a file with exactly one); -1 when none.
int dragPoint(const Document& document);

// Events as scene actions: their names, in INPUTS order.
std::vector<std::string> eventNames(const Document& document);

}  // namespace vitrine::isf
