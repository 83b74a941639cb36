#pragma once
// A file's whole contents, as bytes (empty when it cannot be read): what the tests of writers compare.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace vitrine::test {

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace vitrine::test
