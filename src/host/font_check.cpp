#include "host/font_check.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <fmt/format.h>

namespace vitrine::host {
namespace {

// FreeType's own table of error strings (FT_Error_String needs a FreeType built with them).
#undef FTERRORS_H_
#define FT_ERRORDEF(code, value, text) {value, text},
#define FT_ERROR_START_LIST {
#define FT_ERROR_END_LIST {0, nullptr}};
const struct {
  int code;
  const char* text;
} kFreeTypeErrors[] =
#include FT_ERRORS_H

std::string describe(FT_Error error) {
  for (const auto& entry : kFreeTypeErrors)
    if (entry.text && entry.code == error) return entry.text;
  return fmt::format("FreeType error {}", int(error));
}

}  // namespace

std::string fontProblem(const std::filesystem::path& path) {
  FT_Library library;
  if (const FT_Error error = FT_Init_FreeType(&library)) return "FreeType did not start: " + describe(error);
  FT_Face face;
  FT_Error error = FT_New_Face(library, path.c_str(), 0, &face);
  if (!error) {
    // A file cut short can still open; sizing it and loading a glyph reads the tables the atlas needs.
    error = FT_Set_Pixel_Sizes(face, 0, 17);
    if (!error) error = FT_Load_Char(face, 'A', FT_LOAD_RENDER);
    FT_Done_Face(face);
  }
  FT_Done_FreeType(library);
  return error ? describe(error) : std::string();
}

}  // namespace vitrine::host
