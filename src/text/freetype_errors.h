#pragma once
// FreeType's own sentence for an error code ("unknown file format"), from its error table, since
// FT_Error_String needs a FreeType built with error strings.
#include <string>

namespace vitrine::text {
std::string freetypeError(int error);
}
