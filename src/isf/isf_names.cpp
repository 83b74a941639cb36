#include "isf/isf_names.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace vitrine::isf {
namespace {

// What the generated preamble declares (isf_translate.cpp), and the entry point.
constexpr std::string_view kBuiltIns[] = {
    "TIME", "TIMEDELTA", "DATE", "FRAMEINDEX", "PASSINDEX", "RENDERSIZE", "IMG_PIXEL", "IMG_NORM_PIXEL",
    "IMG_THIS_PIXEL", "IMG_THIS_NORM_PIXEL", "IMG_NORM_THIS_PIXEL", "IMG_SIZE", "main", "ISFFrame", "ISFPass",
};

// GLSL 4.50 keywords and reserved words (the specification's section 3.6), and the built-in functions a
// shader calls, which a uniform of that name would hide.
constexpr std::string_view kGlslWords[] = {
    "attribute", "const", "uniform", "varying", "buffer", "shared", "coherent", "volatile", "restrict",
    "readonly", "writeonly", "atomic_uint", "layout", "centroid", "flat", "smooth", "noperspective", "patch",
    "sample", "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else",
    "subroutine", "in", "out", "inout", "float", "double", "int", "void", "bool", "true", "false", "invariant",
    "precise", "discard", "return", "mat2", "mat3", "mat4", "dmat2", "dmat3", "dmat4", "mat2x2", "mat2x3",
    "mat2x4", "mat3x2", "mat3x3", "mat3x4", "mat4x2", "mat4x3", "mat4x4", "vec2", "vec3", "vec4", "ivec2",
    "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "dvec2", "dvec3", "dvec4", "uint", "uvec2", "uvec3", "uvec4",
    "lowp", "mediump", "highp", "precision", "sampler1D", "sampler2D", "sampler3D", "samplerCube",
    "sampler2DRect", "sampler2DShadow", "sampler2DArray", "isampler2D", "usampler2D", "samplerBuffer",
    "image2D", "texture1D", "texture2D", "texture3D", "textureCube", "sampler", "samplerShadow",
    "subpassInput", "struct", "common", "partition", "active", "asm", "class", "union", "enum", "typedef",
    "template", "this", "resource", "goto", "inline", "noinline", "public", "static", "extern", "external",
    "interface", "long", "short", "half", "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3",
    "hvec4", "fvec2", "fvec3", "fvec4", "filter", "sizeof", "cast", "namespace", "using",
    // built-in functions
    "radians", "degrees", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "pow", "exp",
    "log", "exp2", "log2", "sqrt", "inversesqrt", "abs", "sign", "floor", "trunc", "round", "ceil", "fract",
    "mod", "modf", "min", "max", "clamp", "mix", "step", "smoothstep", "isnan", "isinf", "fma", "length",
    "distance", "dot", "cross", "normalize", "reflect", "refract", "faceforward", "matrixCompMult",
    "transpose", "determinant", "inverse", "lessThan", "greaterThan", "equal", "notEqual", "any", "all", "not",
    "texture", "textureSize", "textureLod", "textureProj", "texelFetch", "textureGrad", "dFdx", "dFdy",
    "fwidth", "texture2DRect", "texture2DProj", "texture2DLod",
};

// Reserved in GLSL 4.50 (or types in Vulkan GLSL) but free names in GLSL 1.10 / ES 1.00.
constexpr std::string_view kReservedSinceGlsl1[] = {
    "sample", "input", "output", "filter", "common", "partition", "active", "resource", "buffer", "shared",
    "subroutine", "coherent", "volatile", "restrict", "readonly", "writeonly", "precise", "sampler",
    "samplerShadow", "texture1D", "texture3D", "textureCube", "image2D", "patch", "subpassInput",
};

template <size_t N>
bool contains(const std::string_view (&words)[N], std::string_view word) {
  return std::find(std::begin(words), std::end(words), word) != std::end(words);
}

}  // namespace

std::string whyNotAName(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.size() > 64) return "is longer than 64 characters";
  if (!(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    return "does not start with a letter or '_', as a GLSL name must";
  for (const char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_'))
      return "holds a character other than letters, digits and '_', as a GLSL name must";
  if (name.find("__") != std::string_view::npos) return "holds \"__\", which GLSL reserves";
  if (name.substr(0, 3) == "gl_") return "starts with \"gl_\", which GLSL reserves";
  if (name.substr(0, 4) == "isf_") return "starts with \"isf_\", which ISF reserves for its own variables";
  if (contains(kBuiltIns, name)) return "is a variable or function ISF declares itself";
  if (contains(kGlslWords, name)) return "is a GLSL keyword or built-in function";
  return {};
}

bool reservedSinceGlsl1(std::string_view word) { return contains(kReservedSinceGlsl1, word); }

}  // namespace vitrine::isf
