#pragma once
// Where the project's own ISF test files are (tests/isf, written from the specification).
#include <filesystem>
#include <string>

namespace vitrine::isf::test {
inline std::filesystem::path isfDir() { return std::filesystem::path(VITRINE_GOLDEN_DIR).parent_path() / "isf"; }
inline std::filesystem::path isfFile(const std::string& name) { return isfDir() / name; }
}  // namespace vitrine::isf::test
