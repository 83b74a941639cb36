#include "support/temp_file.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

namespace vitrine::fuzz {
namespace {

struct Folder {
  std::filesystem::path path;
  Folder() {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/vitrine-fuzz-XXXXXX";
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path = pattern;
  }
  ~Folder() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace

const std::filesystem::path& tempFolder() {
  static const Folder folder;
  return folder.path;
}

std::filesystem::path writeTempFile(std::string_view name, const uint8_t* data, size_t size) {
  const std::filesystem::path path = tempFolder() / name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
  return path;
}

void clearTempFolder() {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(tempFolder(), ec))
    std::filesystem::remove_all(entry.path(), ec);
}

}  // namespace vitrine::fuzz
