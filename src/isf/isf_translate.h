#pragma once
// An ISF file's GLSL (written for desktop GL 2.x/3.x or GLES: gl_FragColor, texture2D, varying, precision
// qualifiers, #version lines) rewritten as Vulkan GLSL 4.50, token by token: the author's code keeps
// its shape and its lines, and a generated preamble declares what ISF promises it: one uniform block of
// the frame's values and the inputs, a push-constant block of the pass's values, a sampler per image,
// isf_FragNormCoord, and IMG_PIXEL, IMG_NORM_PIXEL, IMG_THIS_PIXEL, IMG_THIS_NORM_PIXEL and IMG_SIZE.
//
// Conventions the host keeps (docs/ISF.md):
//   - every image a shader samples is stored bottom row first, as GL stores it: ISF's (0,0) is the
//     bottom-left, texture coordinates and gl_FragCoord are GL's with no flip in the shader, so code
//     that calls texture2D directly sees what it would in GL. The host flips images it brings in (an
//     input scene's frame, imported files) and the output it hands on.
//   - the vertex stage draws 4 vertices as a triangle strip, with no vertex buffer.
//   - #line directives give the generated text source-string 0, the .fs file 1 and the .vs file 2.
#include "isf/isf_document.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vitrine::isf {

// Set 0, binding 0: the uniform block "ISFFrame" (std140): TIME, TIMEDELTA, DATE, FRAMEINDEX, then
// every non-image input in INPUTS order (event and bool as bool, long as int, float, point2D as vec2,
// color as vec4). The offsets below are written into the GLSL as layout(offset = N), so this table is
// the one statement of the layout; reflection of the SPIR-V reads the same.
struct BlockMember {
  enum class Source { Time, TimeDelta, Date, FrameIndex, Input };
  std::string name;
  std::string glslType;  // "float", "int", "bool", "vec2", "vec4"
  uint32_t offset = 0;
  uint32_t size = 0;  // bytes the host writes (a bool is a 4-byte 0 or 1)
  Source source = Source::Input;
  int input = -1;  // Source::Input: the index in Document::inputs
};
struct BlockLayout {
  std::vector<BlockMember> members;
  uint32_t size = 0;  // rounded to 16 bytes, as a std140 block is
};
BlockLayout frameBlock(const Document& document);

// Push constants "ISFPass": RENDERSIZE (vec2, offset 0) and PASSINDEX (int, offset 8), set per pass.
inline constexpr uint32_t kRenderSizeOffset = 0;
inline constexpr uint32_t kPassIndexOffset = 8;
inline constexpr uint32_t kPassBlockBytes = 16;

inline constexpr uint32_t kFrameBlockBinding = 0;
struct SamplerBinding {
  enum class Source { Input, Imported, Target };
  std::string name;
  uint32_t binding = 0;  // set 0
  Source source = Source::Input;
};
// Image, audio and audioFFT inputs in INPUTS order, then IMPORTED, then pass targets: bindings 1, 2, ...
std::vector<SamplerBinding> samplerBindings(const Document& document);

inline constexpr int kMaxVaryingLocations = 16;  // locations the two stages pass between them
// Loop iterations one invocation (a pixel, a vertex) may run, all its loops together, before every
// loop condition reads false: the bound on a runaway shader's work (docs/ISF.md, "Runaway shaders").
inline constexpr int kLoopGuard = 1 << 16;

struct VertexFile {
  std::string text;  // the .vs file's GLSL (no JSON)
  std::string file;  // for complaints
};

struct Translation {
  std::string fragment;  // Vulkan GLSL 4.50
  std::string vertex;
  BlockLayout frame;
  std::vector<SamplerBinding> samplers;
  std::vector<std::string> sourceNames;  // by #line source-string number: generated text, .fs, .vs
};

// Every loop is held to kLoopGuard: one whose trip count its text fixes is charged that count as it
// starts (isf_enter), any other calls isf_guard() in its condition. Throws IsfError with the
// author's file and line: a uniform declared in the code (ISF declares them
// from INPUTS), an attribute (the quad has no vertex buffer), more varyings than kMaxVaryingLocations.
Translation translate(const Document& document, const std::optional<VertexFile>& vertex = std::nullopt);

}  // namespace vitrine::isf
