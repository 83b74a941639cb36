#pragma once
// Whether FreeType can use a font file, and if not, why. Dear ImGui asserts when its font builder
// fails, so the overlay asks here first and falls back to the built-in face, naming the file.
// FreeType only: no ImGui context, no window, so it is unit-tested.
#include <filesystem>
#include <string>

namespace vitrine::host {

// Empty when FreeType opens the file's first face and renders a glyph from it; otherwise FreeType's
// reason ("unknown file format", "invalid stream operation").
std::string fontProblem(const std::filesystem::path& path);

}  // namespace vitrine::host
