#include "text/freetype_errors.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <fmt/format.h>

namespace vitrine::text {
namespace {

#undef FTERRORS_H_
#define FT_ERRORDEF(code, value, text) {value, text},
#define FT_ERROR_START_LIST {
#define FT_ERROR_END_LIST {0, nullptr}};
const struct {
  int code;
  const char* text;
} kFreeTypeErrors[] =
#include FT_ERRORS_H

}  // namespace

std::string freetypeError(int error) {
  for (const auto& entry : kFreeTypeErrors)
    if (entry.text && entry.code == error) return entry.text;
  return fmt::format("FreeType error {}", error);
}

}  // namespace vitrine::text
