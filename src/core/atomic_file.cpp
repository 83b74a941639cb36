#include "core/atomic_file.h"

#include <fmt/format.h>

#include "core/error.h"

namespace vitrine {

void replaceAtomically(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path&)>& write) {
  const auto temporary =
      target.parent_path() / fmt::format(".{}.tmp{}", target.filename().string(), target.extension().string());
  std::error_code ec;
  try {
    write(temporary);
  } catch (...) {
    std::filesystem::remove(temporary, ec);
    throw;
  }
  std::filesystem::rename(temporary, target, ec);
  if (ec) {
    std::filesystem::remove(temporary, ec);
    throw Error(fmt::format("Cannot write {}: {}", target.string(), ec.message()));
  }
}

}  // namespace vitrine
