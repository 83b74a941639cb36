#pragma once
// What this binary is: the version (CMakeLists.txt's project(VERSION), the one place it is set; the
// package and the AppStream release take it from there too) and the commit it was built from.
// Defined in a file the build writes (cmake/BuildInfo.cmake), linked into the executable alone, so a
// new commit recompiles one line, not the library.
#include <string_view>

namespace vitrine {

std::string_view versionNumber();  // "0.1.0"
std::string_view buildCommit();    // `git describe --always --dirty` of the sources, or "unknown"

}  // namespace vitrine
