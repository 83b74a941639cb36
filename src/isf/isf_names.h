#pragma once
// The names an ISF file may not give an input, a pass target or an imported image: those the generated
// shader declares itself (TIME, RENDERSIZE, IMG_PIXEL, isf_FragNormCoord ...), the GLSL keywords and
// built-in functions of the Vulkan GLSL the file is translated to, and anything starting "gl_" or
// "isf_" (reserved to GLSL and to the translation).
#include <string>
#include <string_view>

namespace vitrine::isf {

// Empty if `name` can be a shader variable; otherwise why not, as words that follow the name
// ("is a variable ISF declares itself").
std::string whyNotAName(std::string_view name);

// Identifiers that GLSL 1.x lets a shader use as names but Vulkan GLSL 4.50 reserves ("sample",
// "input", "filter", "sampler", "texture2D" as a type ...): the translation renames them.
bool reservedSinceGlsl1(std::string_view word);

}  // namespace vitrine::isf
