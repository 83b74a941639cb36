#include "host/ui/font_check.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <fmt/format.h>

#include "text/freetype_errors.h"

namespace vitrine::host {
namespace {

std::string describe(FT_Error error) { return text::freetypeError(int(error)); }

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
